# The header-only libraries the kernel and the viewer use, from Debian's own headers, for an Emscripten
# build. Only these headers are exposed (each through a link in a folder of its own): adding /usr/include
# itself would put glibc's headers in front of Emscripten's.
set(NOME_WEB_INCLUDE ${CMAKE_BINARY_DIR}/header_libraries)
file(MAKE_DIRECTORY ${NOME_WEB_INCLUDE})
foreach(header glm nlohmann stb tiny_obj_loader.h tiny_gltf.h)
  if(NOT EXISTS /usr/include/${header})
    message(FATAL_ERROR "/usr/include/${header} is missing: `make web` installs the packages it needs")
  endif()
  file(CREATE_LINK /usr/include/${header} ${NOME_WEB_INCLUDE}/${header} SYMBOLIC)
endforeach()

add_library(glm_headers INTERFACE)
target_include_directories(glm_headers SYSTEM INTERFACE ${NOME_WEB_INCLUDE})
add_library(glm::glm ALIAS glm_headers)

# The implementations Debian ships as shared libraries are compiled here once, from the same headers.
add_library(nome_header_libraries STATIC ${PROJECT_SOURCE_DIR}/web/src/header_libraries.cpp)
target_include_directories(nome_header_libraries SYSTEM PUBLIC ${NOME_WEB_INCLUDE})
# .glb files carry no images here: tinygltf's image loaders stay out of every file that includes it.
target_compile_definitions(nome_header_libraries PUBLIC TINYGLTF_NO_STB_IMAGE TINYGLTF_NO_STB_IMAGE_WRITE
                                                        TINYGLTF_NO_EXTERNAL_IMAGE)
add_library(tinyobjloader::tinyobjloader_double ALIAS nome_header_libraries)
add_library(TinyGLTF::TinyGLTF ALIAS nome_header_libraries)
