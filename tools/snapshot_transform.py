"""A particle snapshot (snapshots/particles_N.vtu, docs/output.md) turned and shifted as a rigid motion.

turn_snapshot(src, dst, angle_deg, before, after) writes dst: src with every point p replaced by
R(angle) (p - before) + after and every velocity v by R(angle) v; every other array is copied byte for byte (the
tensors stay in the grid's frame: the chip analysis reads positions, velocities and scalars only). The snapshot's
appended raw data is edited in place, so the file keeps the exact layout `mpmcut` reads back.
"""
import math
import re
import struct

APPENDED = b'<AppendedData encoding="raw">'


def _array_offset(header, name):
    m = re.search(r'<DataArray[^>]*Name="' + re.escape(name) + r'"[^>]*offset="(\d+)"', header)
    if not m:
        raise ValueError(f"no appended array {name!r}")
    return int(m.group(1))


def turn_snapshot(src, dst, angle_deg, before=(0.0, 0.0), after=(0.0, 0.0)):
    with open(src, "rb") as f:
        data = bytearray(f.read())
    at = data.find(APPENDED)
    if at < 0:
        raise ValueError(f"{src}: no raw appended data")
    header = data[:at].decode()
    if 'header_type="UInt64"' not in header or 'byte_order="LittleEndian"' not in header:
        raise ValueError(f"{src}: expected little-endian data with UInt64 block headers")
    base = data.index(b"_", at) + 1  # the appended data start after the underscore
    points = int(re.search(r'NumberOfPoints="(\d+)"', header).group(1))
    c, s = math.cos(math.radians(angle_deg)), math.sin(math.radians(angle_deg))
    for name, shift in (("Points", True), ("velocity_m_per_s", False)):
        start = base + _array_offset(header, name)
        (nbytes,) = struct.unpack_from("<Q", data, start)
        if nbytes != points * 3 * 8:
            raise ValueError(f"{src}: {name} holds {nbytes} bytes, expected {points} x 3 doubles")
        values = list(struct.unpack_from(f"<{points * 3}d", data, start + 8))
        for k in range(0, len(values), 3):
            x, y = values[k], values[k + 1]
            if shift:
                x, y = x - before[0], y - before[1]
            x, y = c * x - s * y, s * x + c * y
            if shift:
                x, y = x + after[0], y + after[1]
            values[k], values[k + 1] = x, y
        struct.pack_into(f"<{points * 3}d", data, start + 8, *values)
    with open(dst, "wb") as f:
        f.write(data)
