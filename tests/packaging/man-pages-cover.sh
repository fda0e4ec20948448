#!/usr/bin/env bash
# man-pages-cover.sh CLI-BINARY CLI-PAGE SIM-BINARY SIM-PAGE GUI-BINARY GUI-PAGE
#                    AGENT-BINARY|not-built AGENT-PAGE
# The manual pages must describe everything the programs offer: every option in their --help,
# every tipscope-cli command, and every control command tipscope-sim lists for `help`. A new
# option without a line in its manual page fails here. AGENT-BINARY is `not-built` while the tree
# has no tipscope-agent target; its options are then not compared, and the script says so.
set -euo pipefail
. "$(dirname "$0")/common.sh"
need groff groff-base

cli=${1:?tipscope-cli}
cliPage=${2:?tipscope-cli.1}
sim=${3:?tipscope-sim}
simPage=${4:?tipscope-sim.1}
gui=${5:?tipscope}
guiPage=${6:?tipscope.1}
agent=${7:?tipscope-agent or not-built}
agentPage=${8:?tipscope-agent.8}
scratch=$(mktemp -d)
simPid=
cleanup() {
    [ -z "$simPid" ] || kill "$simPid" 2>/dev/null || true
    rm -rf "$scratch"
}
trap cleanup EXIT

# The page as a reader sees it: plain text, wide lines, no hyphenation, no font escapes.
render() {
    LC_ALL=C.UTF-8 groff -man -Tutf8 -rLL=250n -rHY=0 -P-cbou "$1" 2>/dev/null
}

missing=()
# check PAGE-TEXT-FILE WHAT REGEX
check() {
    grep -Eq -- "$3" "$1" || missing+=("$2")
}

options() { grep -oE -- '--[a-z][a-z0-9-]*' | sort -u; }
# An option is described where a paragraph starts with it ("--baud N", "-h, --help"), not
# merely named in the synopsis.
tag() { echo "^ +(-[a-z], )?$1( |$)"; }

# --- tipscope-cli ---------------------------------------------------------------------------
render "$cliPage" >"$scratch/cli.txt"
"$cli" --help >"$scratch/cli-help.txt" || fail "$cli --help failed"
for opt in $(options <"$scratch/cli-help.txt"); do
    check "$scratch/cli.txt" "tipscope-cli option $opt" "$(tag "$opt")"
done
# Commands: the indented words of the "Commands:" block of --help, such as "  detect ...".
commands=$(sed -n '/^Commands:/,/^$/p' "$scratch/cli-help.txt" | grep -oE '^  [a-z]+' | sort -u)
[ -n "$commands" ] || fail "found no commands in $cli --help"
for c in $commands; do
    check "$scratch/cli.txt" "tipscope-cli command $c" "^ +$c( |$)"
done
for code in 0 1 2 3 4 5; do
    check "$scratch/cli.txt" "tipscope-cli exit status $code" "^ +$code +[A-Z]"
done

# --- tipscope-sim ---------------------------------------------------------------------------
render "$simPage" >"$scratch/sim.txt"
"$sim" --help >"$scratch/sim-help.txt" || fail "$sim --help failed"
for opt in $(options <"$scratch/sim-help.txt"); do
    check "$scratch/sim.txt" "tipscope-sim option $opt" "$(tag "$opt")"
done
# The control commands, as the running simulator lists them for `help` (TCP on a free port of
# the loopback interface, so no terminal is needed).
mkfifo "$scratch/in"
"$sim" --tcp 127.0.0.1:0 <"$scratch/in" >"$scratch/sim.out" 2>"$scratch/sim.err" &
simPid=$!
exec 3>"$scratch/in"
echo help >&3
for _ in $(seq 100); do
    [ "$(wc -l <"$scratch/sim.out")" -ge 2 ] && break
    sleep 0.1
done
exec 3>&-
listing=$(sed -n 2p "$scratch/sim.out")
[[ "$listing" == commands:* ]] || fail "tipscope-sim did not list its commands: $(cat "$scratch/sim.err")"
for c in $(echo "${listing#commands:}" | sed 's/ | /\n/g' | awk '{print $1}') unplug plug help; do
    check "$scratch/sim.txt" "tipscope-sim control command $c" "^ +$c( |$)"
done

# --- tipscope (the desktop application; its --help needs no display) ----------------------
render "$guiPage" >"$scratch/gui.txt"
QT_QPA_PLATFORM=offscreen "$gui" --help >"$scratch/gui-help.txt" 2>/dev/null ||
    fail "$gui --help failed"
for opt in $(options <"$scratch/gui-help.txt"); do
    check "$scratch/gui.txt" "tipscope option $opt" "$(tag "$opt")"
done

# --- tipscope-agent (the service) -----------------------------------------------------------
render "$agentPage" >"$scratch/agent.txt"
if [ "$agent" = not-built ]; then
    echo "NOTE: this tree builds no tipscope-agent, so its --help is not compared with its page"
else
    "$agent" --help >"$scratch/agent-help.txt" || fail "$agent --help failed"
    for opt in $(options <"$scratch/agent-help.txt"); do
        check "$scratch/agent.txt" "tipscope-agent option $opt" "$(tag "$opt")"
    done
fi
for code in 0 1 2; do
    check "$scratch/agent.txt" "tipscope-agent exit status $code" "^ +$code +[A-Z]"
done
# What a service manager sends it: reload and stop.
for signal in SIGHUP SIGTERM SIGINT; do
    check "$scratch/agent.txt" "tipscope-agent signal $signal" "^ +(SIG[A-Z]+, )*$signal(,| |$)"
done

if [ ${#missing[@]} -gt 0 ]; then
    echo "FAIL: not described in the manual pages:" >&2
    printf '  %s\n' "${missing[@]}" >&2
    exit 1
fi
echo "PASS: the manual pages describe every option and command"
