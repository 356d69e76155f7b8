# Writes OUTPUT, the man page nome(1), from the program's own help: `nome --help`, `nome COMMAND --help`
# for every command that lists, and the viewer's `nome FILE --help`. The help texts keep their layout
# (.nf), so the page says exactly what the program says. Run at build time with NOME = the built binary.
function(help_text out_var)
  execute_process(COMMAND ${NOME} ${ARGN} OUTPUT_VARIABLE text RESULT_VARIABLE failed)
  if(failed)
    message(FATAL_ERROR "man page: '${NOME} ${ARGN}' failed: ${failed}")
  endif()
  # roff: a backslash is written \e, a minus \- (a bare - may print as a hyphen, and options would not
  # copy); a line starting with . or ' would be a request.
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()

help_text(overview --help)
string(REGEX MATCH "commands:\n.*" listed "${overview}")
string(REGEX MATCHALL "\n  [a-z]+" commands "${listed}")

set(page ".TH NOME 1 \"\" \"nome ${VERSION}\" \"User Commands\"
.SH NAME
nome \\- modeller for 2-manifold surfaces, single-sided ones included
.SH DESCRIPTION
.nf
${overview}.fi
")
foreach(command ${commands})
  string(STRIP "${command}" command)
  help_text(text ${command} --help)
  string(APPEND page ".SH \"nome ${command}\"\n.nf\n${text}.fi\n")
endforeach()
help_text(viewer scene.nome --help)
string(APPEND page ".SH \"THE VIEWER: nome FILE\"\n.nf\n${viewer}.fi
.SH ENVIRONMENT
.TP
.B NOME_SHADERS
a folder of GLSL shaders used before the installed ones (share/nome/shaders beside the bin folder)
.SH FILES
.TP
.I share/nome/assets
example scenes and surfaces
.SH \"SEE ALSO\"
The scene language: share/doc/nome/language.md
")
file(WRITE ${OUTPUT} "${page}")
