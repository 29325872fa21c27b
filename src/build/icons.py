"""Writes the web app's icons (public/icon-192.png, icon-512.png, icon-maskable-512.png) with the
standard library only: a dark blue square, three scallops of a bull-nose tool's passes in amber on
a pale ground line. Run: python3 src/build/icons.py (the PNGs are committed; no build step needs it).
"""
import math
import struct
import zlib
from pathlib import Path

BG = (29, 78, 216)
FG = (251, 191, 36)
GROUND = (230, 236, 245)


def icon(size: int, padding: float) -> bytes:
    rows = []
    r_arc = 0.22 * size
    pitch = 0.26 * size
    base = 0.62 * size
    for y in range(size):
        row = bytearray([0])
        for x in range(size):
            c = BG
            inner = padding * size <= x < (1 - padding) * size and padding * size <= y < (1 - padding) * size
            if inner:
                # Three circular passes; the surface below them is the lower envelope (the scallops).
                k = round((x - size / 2) / pitch)
                cx = size / 2 + k * pitch
                dx = x - cx
                surface = base - math.sqrt(max(0.0, r_arc * r_arc - dx * dx)) + r_arc * 0.55
                if y >= surface and y < base + 0.12 * size:
                    c = FG
                if abs(y - (base + 0.14 * size)) < 0.015 * size:
                    c = GROUND
            row += bytes(c)
        rows.append(bytes(row))
    raw = zlib.compress(b"".join(rows), 9)

    def chunk(tag: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + tag + data + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF)

    return (
        b"\x89PNG\r\n\x1a\n"
        + chunk(b"IHDR", struct.pack(">IIBBBBB", size, size, 8, 2, 0, 0, 0))
        + chunk(b"IDAT", raw)
        + chunk(b"IEND", b"")
    )


out = Path(__file__).resolve().parents[2] / "public"
out.mkdir(exist_ok=True)
(out / "icon-192.png").write_bytes(icon(192, 0.08))
(out / "icon-512.png").write_bytes(icon(512, 0.08))
(out / "icon-maskable-512.png").write_bytes(icon(512, 0.2))
