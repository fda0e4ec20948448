#!/usr/bin/env python3
"""Regenerates the committed seed corpora of tests/fuzz from the guides' worked frames and from
captures of tipscope-sim (its --log output) and tipscope-cli profiles.

usage: seeds.py SIM_LOG [SIM_LOG...] --profiles FILE.json... --out tests/fuzz/corpus

A seed is kept small: single frames, request/answer pairs, and one longer stream, so that the
replay test stays fast and the fuzzer starts from realistic bytes.
"""
import argparse
import os

# The four worked frames of /work/shared/protocol/README.md (W MAT / W LEN, with and without
# addresses).
GUIDE_FRAMES = [
    "0230303031574D41543030333735033E",
    "02574D41543030333735033F",
    "0230303130574C454E30303230300322",
    "02574C454E30303230300323",
]


def write(folder, name, data):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def captured_chunks(logs, per_log=12):
    """Distinct chunks the simulator received (RX) or sent (TX), the first per_log of each log."""
    seen, chunks = set(), []
    for log in logs:
        taken = 0
        for line in open(log):
            if taken == per_log:
                break
            parts = line.split()
            if len(parts) == 2 and parts[0] in ("RX", "TX"):
                b = bytes.fromhex(parts[1])
                key = b[1:9] if len(b) > 9 else b  # one per address/header/command
                if key not in seen:
                    seen.add(key)
                    chunks.append(b)
                    taken += 1
    return chunks


def decoder_seeds(out, chunks):
    d = os.path.join(out, "framedecoder")
    for i, h in enumerate(GUIDE_FRAMES):
        write(d, "guide-%d" % i, bytes([56, 1 + i]) + bytes.fromhex(h))
    for i, c in enumerate(chunks[:24]):
        write(d, "capture-%02d" % i, bytes([56, 7 * i + 3]) + c)
    stream = b"".join(chunks[:12])
    write(d, "capture-stream", bytes([56, 9]) + b"\x00\xff" + stream + stream[:7])


def datafield_seeds(out):
    d = os.path.join(out, "datafield")
    fields = {0: [b"00375", b"-0050", b"99999"], 1: [b"01.60", b"99.99"],
              2: [b"0000ABCD", b"0x1F"], 3: [b"DME-2C", b"9996780"],
              5: [b"00350", b"01.60", b"00001"]}
    for sel, values in fields.items():
        for j, v in enumerate(values):
            write(d, "field-%d-%d" % (sel, j), bytes([sel, j, 17 * j]) + v)
    for j, text in enumerate(["350", "-50", "1.6", "01.60", "disabled", "Stand", " 400 "]):
        for k in range(3):
            write(d, "user-%d-%d" % (j, k), bytes([4, 31 * k, 7 * j + k]) + text.encode())
    write(d, "write-0", bytes([6, 0, 3]) + (350).to_bytes(8, "little"))


def hex_seeds(out, chunks):
    d = os.path.join(out, "hexbytes")
    texts = [" ".join(GUIDE_FRAMES[0][i:i + 2] for i in range(0, len(GUIDE_FRAMES[0]), 2)),
             GUIDE_FRAMES[1].lower(), "0x02,0x57,0x4d", "02:30:30", "\t02 03\n"]
    texts += [c.hex(" ") for c in chunks[:4]]
    for i, t in enumerate(texts):
        write(d, "text-%d" % i, bytes([i % 2]) + t.encode())


def profile_seeds(out, profiles):
    d = os.path.join(out, "profile")
    for p in profiles:
        write(d, os.path.basename(p), open(p, "rb").read())
    write(d, "minimal.json", b'{"format":"tipscope-profile","schema":1,"family":"DME",'
                             b'"values":{"ST1":"00350","HD1":"01.60","D12":"99999"}}')
    # Escapes, nesting and arrays, for the key scan that looks for keys given twice.
    write(d, "nested.json", b'{"format":"tipscope-profile","schema":1,"family":"DME",'
                            b'"extra":{"a":[1,{"b":"\\"q\\\\"},[]],"c":{}},'
                            b'"values":{"\\u0053T1":"00350","A12":"-0050"}}')


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("logs", nargs="+")
    ap.add_argument("--profiles", nargs="*", default=[])
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    chunks = captured_chunks(a.logs)
    decoder_seeds(a.out, chunks)
    datafield_seeds(a.out)
    hex_seeds(a.out, chunks)
    profile_seeds(a.out, a.profiles)


if __name__ == "__main__":
    main()
