#!/usr/bin/env python3
"""A gateway that adds latency: listens on 127.0.0.1:LISTEN, forwards every
connection to 127.0.0.1:TARGET and holds each chunk of bytes, both ways, for
a delay drawn between MIN_MS and MAX_MS (seeded: the same run every time),
keeping their order. Prints "listening" when it accepts connections.

usage: delay_proxy.py LISTEN TARGET MIN_MS MAX_MS [SEED]
"""
import asyncio
import random
import sys


async def pump(reader, writer, rng, lo, hi):
    queue = asyncio.Queue()

    async def deliver():
        while True:
            due, data = await queue.get()
            if data is None:
                break
            wait = due - asyncio.get_running_loop().time()
            if wait > 0:
                await asyncio.sleep(wait)
            writer.write(data)
            await writer.drain()
        writer.close()

    task = asyncio.create_task(deliver())
    try:
        while True:
            data = await reader.read(4096)
            if not data:
                break
            due = asyncio.get_running_loop().time() + rng.uniform(lo, hi) / 1000.0
            await queue.put((due, data))
    except (ConnectionError, OSError):
        pass
    await queue.put((0, None))
    try:
        await task
    except (ConnectionError, OSError):
        pass


async def main():
    listen, target, lo, hi = int(sys.argv[1]), int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
    rng = random.Random(int(sys.argv[5]) if len(sys.argv) > 5 else 26)

    async def handle(client_reader, client_writer):
        try:
            server_reader, server_writer = await asyncio.open_connection("127.0.0.1", target)
        except OSError:
            client_writer.close()
            return
        await asyncio.gather(pump(client_reader, server_writer, rng, lo, hi),
                             pump(server_reader, client_writer, rng, lo, hi))

    server = await asyncio.start_server(handle, "127.0.0.1", listen)
    print("listening", flush=True)
    async with server:
        await server.serve_forever()


if __name__ == "__main__":
    asyncio.run(main())
