#!/usr/bin/env bash
# systemd-unit-verify.sh UNIT AGENT-BINARY|not-built MAN-PAGE
# The agent's unit must load in systemd without a single complaint (`systemd-analyze verify`
# only warns about unknown keys and bad values, and still exits 0, so any line about the unit
# fails here), keep its hardening, and leave the serial ports reachable.
#
# verify also checks that ExecStart's program exists and that Documentation= names a manual page
# `man` can open. The unit names the installed paths, so a copy is verified with ExecStart's
# program replaced by the one just built (or /bin/true while the tree builds no agent, which the
# output says), and MANPATH pointing at a folder that holds MAN-PAGE.
set -euo pipefail
. "$(dirname "$0")/common.sh"
need systemd-analyze systemd
need man man-db

unit=${1:?tipscope-agent.service}
agent=${2:?tipscope-agent or not-built}
page=${3:?tipscope-agent.8}
name=$(basename "$unit")
installed=/usr/bin/tipscope-agent
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# The substitution below must replace exactly the path the package installs the agent to.
grep -qx "ExecStart=$installed --config /etc/tipscope/agent.json" "$unit" ||
    fail "$name does not start $installed --config /etc/tipscope/agent.json"
if [ "$agent" = not-built ]; then
    echo "NOTE: this tree builds no tipscope-agent: ExecStart is verified with /bin/true"
    agent=/bin/true
fi
[ -x "$agent" ] || fail "$agent is not an executable"
sed "s,^ExecStart=$installed ,ExecStart=$agent ," "$unit" >"$scratch/$name"
mkdir -p "$scratch/man/man8"
cp "$page" "$scratch/man/man8/"

echo "== systemd-analyze verify"
status=0
out=$(cd "$scratch" && MANPATH="$scratch/man" systemd-analyze verify "./$name" 2>&1) || status=$?
echo "${out:-(nothing to say)}"
[ "$status" -eq 0 ] || fail "systemd-analyze verify exits with status $status"
# Lines about other units (those the system has, such as network-online.target) are the
# machine's business, not this unit's.
if grep -F "$name" <<<"$out" >/dev/null; then
    fail "systemd-analyze verify complains about $name"
fi

echo "== systemd-analyze security"
# The exposure of the shipped hardening is 2.4 (OK); above 3.0 a protection has gone.
status=0
out=$(cd "$scratch" && systemd-analyze security --offline=true --threshold=30 --no-pager \
    "./$name" 2>&1) || status=$?
grep -F 'Overall exposure level' <<<"$out" || fail "systemd-analyze security said: $out"
[ "$status" -eq 0 ] || fail "the exposure of $name is above 3.0: it lost some of its hardening"

echo "== serial ports"
# Each of these would hide /dev/ttyUSB* or /dev/serial/by-id from the agent (ProtectClock adds a
# device allow list, which shuts out every other device).
for key in PrivateDevices DeviceAllow DevicePolicy ProtectClock; do
    if grep -q "^$key=" "$unit"; then
        fail "$name sets $key=, which cuts the agent off from the serial ports"
    fi
done
grep -qx 'SupplementaryGroups=dialout' "$unit" || fail "$name does not give the agent dialout"
# QSerialPort's lock files live in /run/lock, which ProtectSystem=strict makes read-only.
grep -qx 'ReadWritePaths=-/run/lock' "$unit" || fail "$name leaves /run/lock read-only"
echo "PASS: $name"
