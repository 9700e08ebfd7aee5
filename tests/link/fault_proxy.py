#!/usr/bin/python3
# A faulty RS485 line for link.faults: forwards bytes between two ptys (the
# client's end of one socat pair, the server's end of another) and damages
# them on the way — drops a byte, flips a bit of one, or holds a chunk back
# (a delay inside a frame splits it; a long one outlives the client's
# timeout, so the late answer meets the next request). Seeded: the same
# faults each run. Prints "proxy: N bytes, D dropped, C corrupted, H held"
# to stderr at each SIGUSR1 and at exit (SIGTERM).
# Usage: fault_proxy.py LEFT RIGHT SEED DROP CORRUPT HOLD HOLD_MS
import os
import random
import select
import signal
import sys
import time
import tty

left, right = sys.argv[1], sys.argv[2]
rng = random.Random(int(sys.argv[3]))
drop, corrupt, hold = float(sys.argv[4]), float(sys.argv[5]), float(sys.argv[6])
hold_ms = float(sys.argv[7])
fds = []
for path in (left, right):
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    tty.setraw(fd)
    fds.append(fd)
count = {"bytes": 0, "dropped": 0, "corrupted": 0, "held": 0}


def report(*_):
    sys.stderr.write("proxy: %(bytes)d bytes, %(dropped)d dropped, %(corrupted)d corrupted, %(held)d held\n" % count)
    sys.stderr.flush()


def stop(*_):
    report()
    sys.exit(0)


signal.signal(signal.SIGUSR1, report)
signal.signal(signal.SIGTERM, stop)
sys.stderr.write("proxy: ready\n")
sys.stderr.flush()
while True:
    try:
        ready, _, _ = select.select(fds, [], [], 1.0)
    except InterruptedError:
        continue
    for fd in ready:
        data = os.read(fd, 4096)
        if not data:
            continue
        out = bytearray()
        for b in data:
            count["bytes"] += 1
            r = rng.random()
            if r < drop:
                count["dropped"] += 1
                continue
            if r < drop + corrupt:
                count["corrupted"] += 1
                b ^= 1 << rng.randrange(8)
            out.append(b)
        if rng.random() < hold:
            count["held"] += 1
            # Part of the chunk now, the rest after the hold.
            cut = rng.randrange(len(out) + 1)
            os.write(fds[1 - fds.index(fd)], bytes(out[:cut]))
            time.sleep(rng.uniform(0, hold_ms) / 1000.0)
            out = out[cut:]
        if out:
            os.write(fds[1 - fds.index(fd)], bytes(out))
