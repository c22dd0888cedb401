#!/usr/bin/env python3
"""Writes examples/exp6_curvature_map.png, the Gaussian-curvature map of exp6: a positive cap in
the middle of the 200 x 200 mm sheet and a negative ring around it. Grey 0..255 stands for
K = -4e-5 .. 8e-5 1/mm^2 (the scene's "range"). Standard library only."""
import math
import struct
import zlib
from pathlib import Path

N = 201  # pixels, one per mm
LO, HI = -4e-5, 8e-5


def curvature(x_mm: float, y_mm: float) -> float:
    r = math.hypot(x_mm - 100.0, y_mm - 100.0)
    return 8e-5 * math.exp(-(r / 40.0) ** 2) - 3.5e-5 * math.exp(-(((r - 85.0) / 22.0) ** 2))


def main() -> None:
    rows = []
    for row in range(N):
        y = 200.0 * (N - 1 - row) / (N - 1)  # row 0 is the top of the sheet
        grey = [round(255 * (curvature(200.0 * c / (N - 1), y) - LO) / (HI - LO)) for c in range(N)]
        rows.append(b"\0" + bytes(max(0, min(255, g)) for g in grey))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", N, N, 8, 0, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(b"".join(rows), 9)) + chunk(b"IEND", b"")
    out = Path(__file__).resolve().parent.parent / "examples" / "exp6_curvature_map.png"
    out.write_bytes(png)
    print(out)


if __name__ == "__main__":
    main()
