"""A TCP forwarder, run as a process of its own: ``python tcp_proxy.py PORT HOST:PORT``.

Tests put it between the server and PostgreSQL and kill it to take the database away
from the server without touching the database server itself (which others share);
started again on the same port, it brings the database back. It prints ``ready`` once
it listens.
"""

from __future__ import annotations

import asyncio
import contextlib
import sys


async def _pipe(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
    try:
        while data := await reader.read(65536):
            writer.write(data)
            await writer.drain()
    except ConnectionError:
        pass
    finally:
        with contextlib.suppress(ConnectionError):
            writer.close()


async def _serve(port: int, host: str, target_port: int) -> None:
    async def forward(reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        try:
            up_reader, up_writer = await asyncio.open_connection(host, target_port)
        except OSError:
            writer.close()
            return
        await asyncio.gather(_pipe(reader, up_writer), _pipe(up_reader, writer))

    server = await asyncio.start_server(forward, "127.0.0.1", port, reuse_address=True)
    print("ready", flush=True)
    async with server:
        await server.serve_forever()


def main() -> None:
    """Forward ``127.0.0.1:PORT`` to ``HOST:PORT`` until killed."""
    port, target = sys.argv[1], sys.argv[2]
    host, _, target_port = target.rpartition(":")
    asyncio.run(_serve(int(port), host, int(target_port)))


if __name__ == "__main__":
    main()
