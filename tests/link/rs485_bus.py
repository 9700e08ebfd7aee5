#!/usr/bin/python3
# An RS485 bus of ptys for the link tests: one pty per station (the paths
# given become links to their slave ends); every byte a station sends
# reaches every other station — if both ends are set to the same baud rate,
# parity and stop bits (read from each pty's termios, as the program that
# opened it set them). A receiver at another setting gets what a UART would:
# garbage of about the length the rates give (seeded). With --pace, bytes
# take their time on the wire (10-11 bits each at the sender's rate), so a
# timing figure measured through the bus is a line's.
# Prints "bus: ready" on stderr; on SIGTERM "bus: N bytes, G garbled".
# Usage: rs485_bus.py [--pace] SEED PATH PATH...
import os
import random
import select
import signal
import sys
import termios
import time
import tty

args = sys.argv[1:]
pace = False
if args and args[0] == "--pace":
    pace = True
    args = args[1:]
rng = random.Random(int(args[0]))
paths = args[1:]
masters, slaves = [], []
for path in paths:
    m, s = os.openpty()
    tty.setraw(s)
    try:
        os.unlink(path)
    except FileNotFoundError:
        pass
    os.symlink(os.ttyname(s), path)
    masters.append(m)
    slaves.append(s)  # held open: the master never reads EIO while no station has the port open

SPEEDS = {getattr(termios, n): int(n[1:]) for n in dir(termios) if n.startswith("B") and n[1:].isdigit()}
count = {"bytes": 0, "garbled": 0}


def setting(i):
    a = termios.tcgetattr(masters[i])  # a pty master reports its slave's settings
    cflag = a[2]
    parity = "N" if not cflag & termios.PARENB else ("O" if cflag & termios.PARODD else "E")
    stop = 2 if cflag & termios.CSTOPB else 1
    return SPEEDS.get(a[5], 0), parity, stop


def stop(*_):
    sys.stderr.write("bus: %(bytes)d bytes, %(garbled)d garbled\n" % count)
    sys.stderr.flush()
    for path in paths:
        try:
            os.unlink(path)
        except FileNotFoundError:
            pass
    sys.exit(0)


signal.signal(signal.SIGTERM, stop)
signal.signal(signal.SIGINT, stop)
sys.stderr.write("bus: ready\n")
sys.stderr.flush()
while True:
    try:
        ready, _, _ = select.select(masters, [], [], 1.0)
    except InterruptedError:
        continue
    for fd in ready:
        i = masters.index(fd)
        try:
            data = os.read(fd, 4096)
        except OSError:
            continue
        if not data:
            continue
        count["bytes"] += len(data)
        sender = setting(i)
        if pace and sender[0] > 0:
            bits = 1 + 8 + (0 if sender[1] == "N" else 1) + sender[2]
            time.sleep(len(data) * bits / sender[0])
        for j, other in enumerate(masters):
            if j == i:
                continue
            receiver = setting(j)
            if receiver == sender:
                out = data
            else:
                count["garbled"] += 1
                ratio = receiver[0] / sender[0] if sender[0] else 1.0
                out = bytes(rng.randrange(256) for _ in range(max(1, round(len(data) * ratio))))
            try:
                os.write(other, out)
            except OSError:
                pass
