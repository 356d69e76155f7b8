#!/bin/sh
# Checks the .deb files in PACKAGE_DIR: control data and file lists (dpkg-deb --info/--contents), then
# extracts them (dpkg-deb -x, never dpkg -i) into a temporary folder and runs check_installed.sh there.
# usage: package_test.sh PACKAGE_DIR SOURCE_DIR
set -eu
fail() { echo "package_test: $*" >&2; exit 1; }
runtime=$(ls "$1"/nome_*.deb) dev=$(ls "$1"/nome-dev_*.deb)
root=$(mktemp -d "${TMPDIR:-/tmp}/nome-deb.XXXXXX")
trap 'rm -rf "$root"' EXIT

dpkg-deb --info "$runtime" >"$root/info.txt"
cat "$root/info.txt"
grep -qx " Package: nome" "$root/info.txt" || fail "package name"
depends=$(sed -n 's/^ Depends: //p' "$root/info.txt")
# Computed by dpkg-shlibdeps from the binary's libraries, plus the hand-listed Mesa drivers.
for package in libc6 libstdc++6 libglfw3 libegl1 libosmesa6 libgl1-mesa-dri libtcl8.6; do
  case ", $depends," in *", $package "* | *", $package,"*) ;; *) fail "Depends lacks $package: $depends" ;; esac
done
dpkg-deb --contents "$runtime" | awk '{ print $6 }' >"$root/contents.txt"
for path in ./usr/bin/nome ./usr/share/nome/shaders/mesh.vert ./usr/share/applications/nome.desktop \
  ./usr/share/icons/hicolor/256x256/apps/nome.png ./usr/share/mime/packages/nome.xml \
  ./usr/share/man/man1/nome.1.gz ./usr/share/bash-completion/completions/nome ./usr/share/doc/nome/README.md; do
  grep -qxF "$path" "$root/contents.txt" || fail "$runtime lacks $path"
done
! grep -q "^./usr/include/" "$root/contents.txt" || fail "headers belong in nome-dev"
dpkg-deb --info "$dev" | grep -qx " Package: nome-dev" || fail "nome-dev package name"
for layer in support mesh ops query scene slide io edit; do
  dpkg-deb --contents "$dev" | grep -q "/libnome_$layer\.a$" || fail "nome-dev lacks the kernel's $layer library"
done
dpkg-deb --contents "$dev" | grep -q "/cmake/Nome/NomeConfig\.cmake$" || fail "nome-dev lacks the CMake package"

dpkg-deb -x "$runtime" "$root/tree"
dpkg-deb -x "$dev" "$root/tree"
"$2/tests/install/check_installed.sh" "$root/tree/usr" "$2"
echo "package_test: $(du -k "$runtime" | cut -f1) KB $runtime, $(du -k "$dev" | cut -f1) KB $dev"
