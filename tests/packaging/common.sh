# Helpers shared by the packaging test scripts (sourced, not run).

fail() {
    echo "FAIL: $*" >&2
    exit 1
}

# need TOOL DEBIAN-PACKAGE: stop with a clear message when a tool the test uses is missing.
need() {
    command -v "$1" >/dev/null 2>&1 ||
        fail "'$1' is not installed; add the Debian package '$2' (scripts/install-deps installs it)"
}
