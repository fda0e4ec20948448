#!/usr/bin/env bash
# deb-package.sh CPACK BUILD-DIR SCRATCH VERSION AGENT-BINARY|not-built
# Builds the Debian package from the binaries already built in BUILD-DIR (cpack runs the same
# configuration as `cmake --build BUILD-DIR --target package`, but writes into SCRATCH), then
# checks its control fields, maintainer scripts and contents, unpacks it with `dpkg -x` into a
# scratch root, and runs the programs from there. AGENT-BINARY is `not-built` while the tree has
# no tipscope-agent target: the package then cannot hold the agent, and the output says so.
set -euo pipefail
. "$(dirname "$0")/common.sh"
need dpkg dpkg
need dpkg-deb dpkg
need dpkg-shlibdeps dpkg-dev
need file file
need readelf binutils

cpack=${1:?cpack}
build=${2:?build directory}
scratch=${3:?scratch directory}
version=${4:?project version}
agent=${5:?tipscope-agent or not-built}
programs=(tipscope tipscope-cli tipscope-sim)
if [ "$agent" = not-built ]; then
    echo "NOTE: this tree builds no tipscope-agent: the package is checked without it"
else
    programs+=(tipscope-agent)
fi

rm -rf "$scratch"
mkdir -p "$scratch/out"
echo "== building the package (log: $scratch/cpack.log)"
if ! "$cpack" --config "$build/CPackConfig.cmake" -B "$scratch/out" >"$scratch/cpack.log" 2>&1; then
    cat "$scratch/cpack.log" >&2
    fail "cpack could not build the package"
fi
arch=$(dpkg --print-architecture)
deb="$scratch/out/tipscope_${version}_${arch}.deb"
[ -f "$deb" ] || fail "no $deb; cpack made: $(ls "$scratch/out")"

echo "== control fields"
dpkg-deb -I "$deb"
field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = tipscope ] || fail "Package is '$(field Package)'"
[ "$(field Version)" = "$version" ] || fail "Version is '$(field Version)', not $version"
[ "$(field Architecture)" = "$arch" ] || fail "Architecture is '$(field Architecture)'"
[ "$(field Section)" = electronics ] || fail "Section is '$(field Section)'"
[ "$(field Maintainer)" = "TipScope maintainers" ] || fail "Maintainer is '$(field Maintainer)'"
[ -z "$(field Homepage)" ] || fail "the package names a Homepage: $(field Homepage)"
depends=$(field Depends)
# dpkg-shlibdeps computed these from what the executables link; none is listed by hand.
for lib in libqt6core6 libqt6gui6 libqt6widgets6 libqt6network6 libqt6serialport6; do
    [[ ", $depends," =~ ,\ $lib[\ ,] ]] || fail "Depends does not name $lib: $depends"
done
# ... and these are: a Qt plugin (the journal's SQLite driver) and the tool postinst uses.
for package in libqt6sql6-sqlite adduser; do
    [[ ", $depends," =~ ,\ ${package}[\ ,] ]] || fail "Depends does not name $package: $depends"
done

echo "== maintainer scripts"
control="$scratch/control"
dpkg-deb -e "$deb" "$control"
for script in postinst prerm postrm; do
    [ -x "$control/$script" ] || fail "the package has no executable $script"
    sh -n "$control/$script" || fail "$script is not a valid shell script"
    # Nothing starts unless the administrator enables it.
    if grep -nE 'systemctl +(enable|start|restart|reload)|--now' "$control/$script"; then
        fail "$script enables or starts the service"
    fi
done
grep -qE '^ *adduser .*--system .*--home /var/lib/tipscope .*tipscope$' "$control/postinst" ||
    fail "postinst does not make the system user tipscope"
grep -qE '^ *adduser .*tipscope dialout$' "$control/postinst" ||
    fail "postinst does not add the user tipscope to dialout"
for conffile in /etc/tipscope/agent.json /etc/tipscope/workspace.json; do
    grep -qxF "$conffile" "$control/conffiles" || fail "$conffile is not a conffile"
done

echo "== contents"
dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's,^\./,/,' >"$scratch/contents.txt"
expected=(
    "${programs[@]/#//usr/bin/}"
    /usr/share/applications/tipscope.desktop
    /usr/share/icons/hicolor/scalable/apps/tipscope.svg
    /usr/share/metainfo/io.github.tipscope.TipScope.metainfo.xml
    /usr/share/man/man1/tipscope-cli.1.gz
    /usr/share/man/man1/tipscope-sim.1.gz
    /usr/share/man/man8/tipscope-agent.8.gz
    /usr/share/doc/tipscope/README.dialout.md
    /lib/systemd/system/tipscope-agent.service
    /etc/tipscope/agent.json
    /etc/tipscope/workspace.json
)
# Whatever translations the build made must be in the package too (none is fine).
while IFS= read -r qm; do
    expected+=("/usr/share/tipscope/translations/$(basename "$qm")")
done < <(find "$build" -name '*.qm' -type f -not -path '*/_CPack_Packages/*' \
    -not -path '*/share/tipscope/translations/*' | sort)
for path in "${expected[@]}"; do
    grep -qxF "$path" "$scratch/contents.txt" || fail "the package lacks $path"
done
echo "the package holds all ${#expected[@]} expected files"

echo "== unpacked into $scratch/root"
root="$scratch/root"
dpkg -x "$deb" "$root"
for exe in "${programs[@]}"; do
    if readelf -d "$root/usr/bin/$exe" | grep -E 'RPATH|RUNPATH' | grep -qF "$build"; then
        fail "$exe would load libraries from the build tree"
    fi
done
for page in man1/tipscope-cli.1 man1/tipscope-sim.1 man8/tipscope-agent.8; do
    gzip -t "$root/usr/share/man/$page.gz" || fail "$page.gz is not a valid gzip file"
done

run() {
    local expected=$1
    shift
    local out
    out=$("$@" 2>&1) || fail "'$*' failed: $out"
    [[ "$out" == *"$expected"* ]] || fail "'$*' printed '$out', expected '$expected'"
    echo "ok: $* -> $out"
}
run "tipscope-cli $version" "$root/usr/bin/tipscope-cli" --version
run "SMN DME-2C" "$root/usr/bin/tipscope-cli" --demo read SMN
run "$version" "$root/usr/bin/tipscope-sim" --version
run "$version" env QT_QPA_PLATFORM=offscreen "$root/usr/bin/tipscope" --version
# The example the package installs works as it is: its workspace is the demo line...
run "[demo] 01 DME-2C" "$root/usr/bin/tipscope-cli" --workspace "$root/etc/tipscope/workspace.json" \
    detect
# ... and the agent accepts the configuration naming it.
if [ "$agent" != not-built ]; then
    run "$version" "$root/usr/bin/tipscope-agent" --version
    "$root/usr/bin/tipscope-agent" --check --config "$root/etc/tipscope/agent.json" ||
        fail "tipscope-agent --check refuses the example configuration"
fi
echo "PASS: $deb"
