#!/usr/bin/python3
# A foreign Modbus RTU controller for the link tests: pymodbus (Debian's
# python3-pymodbus 3.0) serving a fixed register image on a pty, as a K528-05
# would hold it: C40 (F ОБЫЧНАЯ X) = 123456 at Z4124/Z4125 low word first,
# C17 (N ДОС X) = 2 at Z4101, C1 and C7 bits of Z4100, R5 = -7 at 5010/5011,
# mode F2 at 6000, no programs, the transfer status 1 "ready" with an empty
# text (no messages); the setup R-parameters of the extended map: R150 = 1,
# R200 = 20000, R231 = -123456, and the positioner's own R158 = 2 and R222 =
# 777 (not presets of a pulled file). Usage: foreign_controller.py PORT
import sys

from pymodbus.datastore import ModbusSequentialDataBlock, ModbusServerContext, ModbusSlaveContext
from pymodbus.server import StartSerialServer
from pymodbus.transaction import ModbusRtuFramer

regs = [0] * 10000
regs[4100] = (1 << 0) | (1 << 4) | (1 << 6)  # C1 axis present, C5 0.001, C7 diameter
regs[4101] = 2                               # C17
regs[4124] = 123456 & 0xFFFF                 # C40 low
regs[4125] = 123456 >> 16                    # C40 high
regs[5010] = (-7) & 0xFFFF                   # R5 low
regs[5011] = ((-7) >> 16) & 0xFFFF           # R5 high
def r(n, v):
    regs[5000 + 2 * n] = v & 0xFFFF
    regs[5001 + 2 * n] = (v >> 16) & 0xFFFF


r(150, 1)
r(200, 20000)
r(231, -123456)
r(158, 2)
r(222, 777)
regs[6000] = 2
regs[7002] = 1
context = ModbusServerContext(
    slaves={1: ModbusSlaveContext(hr=ModbusSequentialDataBlock(0, regs), zero_mode=True)}, single=False)
StartSerialServer(context=context, framer=ModbusRtuFramer, port=sys.argv[1], baudrate=115200, parity="N")
