#!/bin/sh
# `cmake --install` of BUILD_DIR into a temporary DESTDIR (never the system), then check_installed.sh on it.
# usage: install_test.sh BUILD_DIR SOURCE_DIR CXX_COMPILER
set -eu
root=$(mktemp -d "${TMPDIR:-/tmp}/nome-destdir.XXXXXX")
trap 'rm -rf "$root"' EXIT
DESTDIR=$root cmake --install "$1" --prefix /usr >"$root.log" || { cat "$root.log"; rm -f "$root.log"; exit 1; }
rm -f "$root.log"
"$2/tests/install/check_installed.sh" "$root/usr" "$2" "$3"
