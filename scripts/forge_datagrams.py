#!/usr/bin/env python3
"""A third party on the loopback address: sends what must never drive a robot to the given
ports until stopped (SIGTERM) — rubbish, datagrams signed with a guessed key, well-signed
ones from the wrong source, and a well-signed torque that is not a number.

    forge_datagrams.py KEY PORT [PORT...]
"""
import hashlib
import hmac
import signal
import socket
import struct
import sys
import time


def datagram(kind, values, key, session=1, sequence=1):
    """docs/realtime.md's layout: header, values, text length, text, 16-byte HMAC-SHA256."""
    body = b"CBBG" + struct.pack("<BBHIIdQ", 1, kind, len(values), session, sequence, 0.0, 0)
    body += b"".join(struct.pack("<d", v) for v in values) + b"\x00"
    return body + hmac.new(key, body, hashlib.sha256).digest()[:16]


def main():
    key = sys.argv[1].encode()
    ports = [int(port) for port in sys.argv[2:]]
    torque = 5  # the kind of a torque datagram
    sends = [b"\x01\x02\x03",
             datagram(torque, [1000.0, 1000.0], b"a guess"),
             datagram(torque, [1000.0, 1000.0], key),
             datagram(torque, [float("nan"), 0.0], key)]
    signal.signal(signal.SIGTERM, lambda *_: sys.exit(0))
    with socket.socket(socket.AF_INET, socket.SOCK_DGRAM) as sock:
        while True:
            for port in ports:
                for payload in sends:
                    sock.sendto(payload, ("127.0.0.1", port))
            time.sleep(0.005)


if __name__ == "__main__":
    main()
