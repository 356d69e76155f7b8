# `make package`: two Debian packages from the install rules, by CPack's DEB generator:
#   nome      the program (runtime component); its library dependencies computed by dpkg-shlibdeps
#   nome-dev  the kernel's static library, headers and CMake package (development component)
# CPack rather than a debian/ folder: the install rules are already the one list of what goes where,
# and a local `make package` needs no source package, changelog or debhelper.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME nome)
set(CPACK_PACKAGE_VENDOR "Nome")
set(CPACK_PACKAGE_CONTACT "Nome developers <nome@invalid>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)

set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME nome)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_SECTION graphics)
# Descriptions: the first line is the package's summary; CPack indents the others as dpkg wants.
set(CPACK_DEBIAN_RUNTIME_DESCRIPTION "modeller for 2-manifold surfaces, single-sided ones included
Nome describes coarse meshes in a small scene language whose parameters become sliders, glues
pieces together, smooths them with Catmull-Clark subdivision and thickens the result into a closed
solid for 3D printing. Mobius bands and Klein bottles are first-class: every algorithm works on
one-sided surfaces. Viewer (GLFW + Dear ImGui) and command line (info, export, render headless).")
# Drawing needs Mesa's drivers at run time (dlopen'ed, so dpkg-shlibdeps cannot see them).
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "libgl1-mesa-dri")

set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME nome-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_DEVELOPMENT_DESCRIPTION "Nome's mesh kernel as a static C++20 library
find_package(Nome) gives Nome::kernel: the index-array mesh, Catmull-Clark subdivision and
the offset that are right on one-sided surfaces, the scene language, OBJ/STL/SIF input and output.")
# A static library has no shared-library dependencies to compute: these are its headers' and CMake
# package's (find_dependency(glm), find_dependency(tinyobjloader), find_dependency(TinyGLTF)) and Tcl, which
# the slide layer links by its library path.
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS "libglm-dev, libtinyobjloader-dev, libtinygltf-dev, tcl8.6-dev")

include(CPack)
