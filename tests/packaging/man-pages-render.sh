#!/usr/bin/env bash
# man-pages-render.sh PAGE...
# Each manual page must format without a single groff warning (the check lintian makes with
# `man --warnings`), in the UTF-8 locale the pages are read in.
set -euo pipefail
. "$(dirname "$0")/common.sh"
need groff groff-base

[ $# -gt 0 ] || fail "no manual page given"
export LC_ALL=C.UTF-8
for page in "$@"; do
    [ -f "$page" ] || fail "$page does not exist"
    warnings=$(groff -man -Tutf8 -ww -z "$page" 2>&1) || fail "groff cannot format $page: $warnings"
    [ -z "$warnings" ] || fail "groff warns about $page:"$'\n'"$warnings"
    grep -q '^\.SH EXIT STATUS' "$page" || fail "$page has no EXIT STATUS section"
    grep -q '^\.SH EXAMPLES' "$page" || fail "$page has no EXAMPLES section"
    grep -q 'dialout' "$page" || fail "$page does not mention the dialout group"
    echo "PASS: $page"
done
