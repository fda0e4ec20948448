#!/usr/bin/env bash
# validate-metadata.sh metainfo FILE | desktop FILE
# Validates the AppStream metadata with appstreamcli (offline: --no-net) or the desktop entry
# with desktop-file-validate. Any warning or error fails.
set -euo pipefail
. "$(dirname "$0")/common.sh"

kind=${1:?metainfo or desktop}
file=${2:?file to validate}
[ -f "$file" ] || fail "$file does not exist"

case "$kind" in
metainfo)
    need appstreamcli appstream
    appstreamcli validate --no-net "$file" || fail "appstreamcli rejects $file"
    ;;
desktop)
    need desktop-file-validate desktop-file-utils
    # desktop-file-validate exits 0 on hints and warnings too: any output counts as a failure.
    out=$(desktop-file-validate "$file" 2>&1) || fail "desktop-file-validate rejects $file: $out"
    [ -z "$out" ] || fail "desktop-file-validate complains about $file: $out"
    ;;
*)
    fail "unknown kind '$kind'"
    ;;
esac
echo "PASS: $file"
