#!/bin/sh
# Checks an installed Nome tree at PREFIX (a DESTDIR install or extracted packages, never the system):
# its files, the installed nome (info, render, version --verbose using PREFIX's shaders), the desktop
# entry, the MIME type, the man page, bash completion, and a find_package(Nome) program built against it.
# usage: check_installed.sh PREFIX SOURCE_DIR [CXX_COMPILER]
set -eu
prefix=$(realpath "$1")
source_dir=$2
compiler=${3:-c++}
nome=$prefix/bin/nome
work=$(mktemp -d "${TMPDIR:-/tmp}/nome-check.XXXXXX")
trap 'rm -rf "$work"' EXIT
fail() { echo "check_installed: $*" >&2; exit 1; }
unset NOME_SHADERS
share=$prefix/share

for file in bin/nome share/nome/shaders/mesh.vert share/nome/shaders/mesh.frag share/nome/assets/mobius_band.obj \
  share/applications/nome.desktop share/icons/hicolor/256x256/apps/nome.png share/mime/packages/nome.xml \
  share/man/man1/nome.1.gz share/bash-completion/completions/nome share/doc/nome/README.md \
  include/nome/mesh/mesh.hpp; do
  [ -e "$prefix/$file" ] || fail "missing $file"
done

# The installed program, with the installed shaders (not the source tree's, not the embedded copy).
version=$("$nome" --version --verbose)
echo "$version"
echo "$version" | grep -qx "nome [0-9.]* (git [0-9a-f]*\(-dirty\)\{0,1\})" || fail "no version line"
echo "$version" | grep -q "^GL backend: EGL" || fail "no EGL backend"
echo "$version" | grep -qx "shaders: $share/nome/shaders" || fail "the installed nome does not use $share/nome/shaders"
"$nome" info "$share/nome/assets/mobius_band.nome" >"$work/info.txt"
grep -q "orientable *no" "$work/info.txt" || { cat "$work/info.txt"; fail "nome info: a Möbius band is not orientable"; }
"$nome" render "$share/nome/assets/mobius_band.nome" -o "$work/band.png" --size 64x48 --verbose 2>"$work/render.txt"
[ "$(head -c 4 "$work/band.png" | tail -c 3)" = PNG ] || { cat "$work/render.txt"; fail "nome render wrote no PNG"; }

# Desktop integration: the entry validates, the MIME database accepts the type and its globs.
desktop-file-validate "$share/applications/nome.desktop" || fail "invalid desktop entry"
grep -qx "MimeType=text/x-nome;" "$share/applications/nome.desktop" || fail "the desktop entry does not open scenes"
mkdir -p "$work/mime/packages" && cp "$share/mime/packages/nome.xml" "$work/mime/packages/"
XDG_DATA_DIRS=$work update-mime-database "$work/mime" && grep -q "text/x-nome:\*\.nom$" "$work/mime/globs" || fail "MIME type not registered"
grep -q "text/x-nome:\*\.nome$" "$work/mime/globs" || fail "no *.nome glob"
zcat "$share/man/man1/nome.1.gz" >"$work/nome.1"
for section in '.SH "nome render"' '.SH "nome info"' '.SH "nome version"' '.SH "THE VIEWER: nome FILE"'; do
  grep -qxF "$section" "$work/nome.1" || fail "man page lacks $section"
done
grep -qF -- '\-\-subdiv\-after' "$work/nome.1" || fail "man page lacks the pipeline options"

# Bash completion of commands (from nome --help) and of a command's options (from its --help).
complete_words() {
  (cd "$work" && bash -c '. "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _nome "$0"; echo " ${COMPREPLY[*]} "' \
    "$nome" "$share/bash-completion/completions/nome" "$@")
}
case $(complete_words nome re) in *" render "*) ;; *) fail "bash completion of commands" ;; esac
case $(complete_words nome render --subdiv) in *" --subdiv-after "*) ;; *) fail "bash completion of options" ;; esac

# A program of our users': find_package(Nome) against this tree only.
launcher=$(command -v ccache || true)
cmake -S "$source_dir/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF -DCMAKE_CXX_COMPILER="$compiler" \
  ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"} >"$work/configure.txt" || { cat "$work/configure.txt"; fail "consumer configure"; }
grep -q "^Nome_DIR:PATH=$prefix/" "$work/consumer/CMakeCache.txt" || fail "find_package(Nome) found another Nome"
cmake --build "$work/consumer" >"$work/build.txt" || { cat "$work/build.txt"; fail "consumer build"; }
result=$("$work/consumer/consumer" "$share/nome/assets/mobius_band.obj")
echo "consumer: $result"
[ "$result" = "faces 2048 chi 0 orientable 0" ] || fail "consumer printed '$result'"
echo "check_installed: $prefix is a working Nome"
