#!/usr/bin/env bash
# The installed tree works as a user and another code would use it (CTest test install_consumer):
# `cmake --install` into a fresh prefix; a consumer project outside the tree builds against it
# with find_package(ejecta) and runs a scene through ejecta::sim; the installed binary runs a
# shipped scene by name from an unrelated directory; the manual page, the bash completion and the
# Python reader are where they should be and work.
#   check_install.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$1 source=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

cmake --install "$build" --prefix "$prefix" > "$work/install.log"
echo "installed into $prefix: $(find "$prefix" -type f | wc -l) files"

cmake -S "$source/tests/install/consumer" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
      -DCMAKE_BUILD_TYPE=Release > "$work/consumer.configure.log" || { cat "$work/consumer.configure.log"; exit 1; }
cmake --build "$work/consumer" > "$work/consumer.build.log" || { cat "$work/consumer.build.log"; exit 1; }
"$work/consumer/consumer"

# The binary finds its libraries through its RUNPATH, not the build tree.
cd "$work"
"$prefix/bin/ejecta" --version
scenes=$("$prefix/bin/ejecta" scenes)
grep -q "^impact_rz " <<< "$scenes" || { echo "ejecta scenes lacks impact_rz"; exit 1; }
"$prefix/bin/ejecta" run sod_1d --set "time.t_end=0.01 s" --out "$work/run" --quiet --no-charts --threads 1
test -f "$work/run/summary.json"
# (Outputs captured first: grep -q closing a pipe early would fail the pipeline under pipefail.)
libraries=$(ldd "$prefix/bin/ejecta")
if grep -qF "$build" <<< "$libraries"; then echo "the installed binary links the build tree"; exit 1; fi

man_page=$prefix/share/man/man1/ejecta.1
grep -q '^\.SH COMMANDS' "$man_page" && grep -q 'ejecta run' "$man_page" || { echo "$man_page lacks its commands"; exit 1; }
if command -v groff > /dev/null; then
  warnings=$(groff -man -Tutf8 -ww -z "$man_page" 2>&1 || true)
  [ -z "$warnings" ] || { echo "groff: $warnings"; exit 1; }
fi
completion=$prefix/share/bash-completion/completions/ejecta
words=$(bash -c "source '$completion'; COMP_WORDS=(ejecta sc); COMP_CWORD=1; _ejecta; echo \${COMPREPLY[*]}")
[ "$words" = "scenes" ] || { echo "completion of 'ejecta sc': '$words'"; exit 1; }
words=$(bash -c "source '$completion'; COMP_WORDS=(ejecta run --ov); COMP_CWORD=2; _ejecta; echo \${COMPREPLY[*]}")
[ "$words" = "--overwrite" ] || { echo "completion of 'ejecta run --ov': '$words'"; exit 1; }
words=$(bash -c "PATH='$prefix/bin':\$PATH; source '$completion'; COMP_WORDS=(ejecta run impact_r); COMP_CWORD=2; _ejecta; echo \${COMPREPLY[*]}")
[[ "$words" == *impact_rz* ]] || { echo "completion of 'ejecta run impact_r': '$words'"; exit 1; }

if [ -x /usr/bin/python3 ] && /usr/bin/python3 -c "import numpy, h5py" 2> /dev/null; then
  PYTHONPATH=$prefix/share/ejecta/python /usr/bin/python3 -c "import ejecta, sys; r = ejecta.load_run(sys.argv[1]); print('python:', r.series)" "$work/run"
fi
test -f "$prefix/include/ejecta/sim/run/run.hpp"
test -f "$prefix/share/ejecta/scenes/impact_rz.toml"
test -f "$prefix/share/doc/ejecta/README.md"
# The Debian package of the same tree (CPack): its dependencies from dpkg-shlibdeps, and a binary
# that runs from the unpacked files.
if command -v cpack > /dev/null && command -v dpkg-deb > /dev/null; then
  cpack -G DEB -B "$work/deb" --config "$build/CPackConfig.cmake" > "$work/cpack.log" || { cat "$work/cpack.log"; exit 1; }
  debs=("$work"/deb/ejecta_*.deb)
  [ ${#debs[@]} -eq 1 ] && [ -f "${debs[0]}" ] || { echo "cpack made ${#debs[@]} packages: ${debs[*]}"; exit 1; }
  deb=${debs[0]}
  control=$(dpkg-deb -I "$deb")
  grep -q "Depends: .*libhdf5" <<< "$control" || { echo "$control"; echo "the package lists no library dependencies"; exit 1; }
  dpkg-deb -x "$deb" "$work/unpacked"
  "$work/unpacked/usr/bin/ejecta" scenes --kind study > /dev/null
  echo "package: $(basename "$deb") ($(du -k "$deb" | cut -f1) kB)"
fi
echo "install_consumer: the installed tree works"
