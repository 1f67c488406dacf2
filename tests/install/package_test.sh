#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# package_test.sh BUILD_DIR: the Debian package as a user gets it. CPack builds the .deb from the
# build (cmake/Install.cmake), dpkg-deb unpacks it into a temporary root (what dpkg would install,
# without touching the machine), and the installed tree is run on its own: no build or source
# folder in its environment, a home and model cache of its own. Checked: `wrc --help`; a
# geometry command against the build's own output; the shipped files where they belong; and a
# `wrc query`, which starts the installed wrc-contactd (found beside the installed wrc) and
# prints its answer. Run inside a private network namespace (clients/lib/netns.sh) for the query.
set -euo pipefail
build=${1:?usage: package_test.sh BUILD_DIR}
build=$(cd "$build" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

(cd "$dir" && cpack -G DEB -B "$dir/package" --config "$build/CPackConfig.cmake" >cpack.log 2>&1) ||
  { tail -30 "$dir/cpack.log"; fail "cpack failed"; }
deb=$(ls "$dir"/package/wrc_*.deb 2>/dev/null | head -1)
[ -n "$deb" ] || { ls -R "$dir/package" | head; fail "no wrc_*.deb"; }
info=$(dpkg-deb --info "$deb")  # (not piped into grep -q: pipefail would see dpkg-deb's SIGPIPE)
grep -q "Depends:.*liblcm" <<<"$info" || { echo "$info"; fail "the package does not depend on LCM"; }
root=$dir/root
dpkg-deb -x "$deb" "$root"

for f in usr/bin/wrc usr/bin/wrc-contactd usr/bin/wrc-geometryd usr/bin/wrc-dynamicsd usr/bin/wrc-pingd \
         usr/share/wrc/profiles/MBench_S1002_v3.prw usr/share/wrc/profiles/launch/default.txt \
         usr/share/wrc/parameters/benchmark.json usr/share/java/wrc_lcmtypes_java.jar \
         usr/share/doc/wrc/LICENSE usr/share/doc/wrc/NOTICE usr/share/doc/wrc/README.md usr/share/doc/wrc/docs/spline-model.md; do
  [ -e "$root/$f" ] || fail "the package has no /$f"
done

# The installed tree alone: no WRC_BUILD_DIR / WRC_ROOT, a PATH without the build.
run() { env -i PATH=/usr/bin:/bin HOME="$dir/home" WRC_CACHE_DIR="$dir/cache" LCM_DEFAULT_URL="${LCM_DEFAULT_URL:-}" "$@"; }
mkdir -p "$dir/home"
run "$root/usr/bin/wrc" --help >help.txt 2>&1 || { cat help.txt; fail "wrc --help failed"; }
grep -q "geometry" help.txt || fail "wrc --help lists no geometry command"
args=(geometry --y-from -0.002 --y-to 0.002 --y-step 0.001)
run "$root/usr/bin/wrc" "${args[@]}" >installed.csv 2>err.txt || { cat err.txt; fail "installed wrc geometry failed"; }
"$build/clients/wrc-cli" "${args[@]}" >built.csv 2>/dev/null
cmp -s installed.csv built.csv || { diff installed.csv built.csv | head; fail "installed geometry differs from the build's"; }
[ "$(wc -l <installed.csv)" = 6 ] || fail "geometry: not 5 rows"
run "$root/usr/bin/wrc" query --model onepoint --y 0.003 >query.txt 2>err.txt ||
  { cat err.txt query.txt; fail "installed wrc query failed"; }
grep -q "^wheel,s,angle" query.txt || { cat query.txt err.txt; fail "no query answer"; }
grep -q "$root/usr/bin/wrc-contactd" err.txt query.txt ||
  { cat err.txt; fail "the query did not start the installed wrc-contactd"; }
echo "package $(basename "$deb"): $(du -k "$deb" | cut -f1) kB; installed wrc answered --help, geometry and a query"
