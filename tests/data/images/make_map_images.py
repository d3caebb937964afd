# Writes the small image_map / bump_map / material_map probe images (pure Python: zlib +
# struct). Uneven sizes and colours on purpose, so that a flipped axis, a shifted texel or a
# wrong decoding shows.
import math, struct, sys, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_writer import chunk, write_png
out = sys.argv[1]
W, H = 20, 14
def png(name, colour_type, depth, rows, extra=b""):
    write_png(os.path.join(out, name), W, H, colour_type, depth, rows, extra)
def colour(x, y):  # a gradient with a bright corner marker at the top left and a dark stripe
    r = int(255 * x / (W - 1))
    g = int(255 * (1 - y / (H - 1)))
    b = int(127 + 120 * math.sin(x * 0.9 + y * 0.4))
    if x < 3 and y < 2: r, g, b = 255, 255, 255
    if x == 12: r, g, b = r // 4, g // 4, b // 4
    return r, g, b
rgb = [bytes(c for x in range(W) for c in colour(x, y)) for y in range(H)]
png("map_rgb.png", 2, 8, rgb)
png("map_gama.png", 2, 8, rgb, chunk(b"gAMA", struct.pack(">I", 45455)))
png("map_srgb.png", 2, 8, rgb, chunk(b"sRGB", b"\0"))
def alpha(x, y): return max(0, min(255, int(255 * (0.5 + 0.5 * math.cos(x * 0.5) * math.cos(y * 0.7)))))
rgba = [bytes(v for x in range(W) for v in colour(x, y) + (alpha(x, y),)) for y in range(H)]
png("map_rgba.png", 6, 8, rgba)
# palette of 6 entries, entry 4 half transparent (tRNS); indices in diagonal bands
plte = bytes([250, 40, 30, 40, 200, 60, 30, 60, 230, 240, 220, 40, 200, 60, 220, 20, 20, 20])
pal = [bytes((x + 2 * y) // 3 % 6 for x in range(W)) for y in range(H)]
png("map_palette.png", 3, 8, pal, chunk(b"PLTE", plte) + chunk(b"tRNS", bytes([255, 255, 255, 255, 128, 255])))
# The same palette image as an interlaced GIF (POV-Ray 3.7 shows its rows in the stored order),
# entry 4 transparent (graphic control extension),
# coded as 4-bit literals with a clear code before every fifth one, so no code grows wider.
def gif(name, w, h, palette, rows, transparent):
    order = [y for start, step in ((0, 8), (4, 8), (2, 4), (1, 2)) for y in range(start, h, step)]
    codes = []
    for n, i in enumerate(i for y in order for i in rows[y]):
        if n % 5 == 0: codes.append(8)
        codes.append(i)
    codes.append(9)
    acc = bits = 0
    data = bytearray()
    for c in codes:
        acc |= c << bits; bits += 4
        while bits >= 8: data.append(acc & 255); acc >>= 8; bits -= 8
    if bits: data.append(acc)
    table = palette + bytes(48 - len(palette))
    b = b"GIF89a" + struct.pack("<HHBBB", w, h, 0x83, 0, 0) + table
    b += bytes([0x21, 0xF9, 4, 1, 0, 0, transparent, 0])
    b += b"\x2c" + struct.pack("<HHHHB", 0, 0, w, h, 0x40) + bytes([3])
    for i in range(0, len(data), 255): b += bytes([len(data[i:i + 255])]) + bytes(data[i:i + 255])
    open(os.path.join(out, name), "wb").write(b + b"\x00\x3b")
gif("map_palette.gif", W, H, plte, pal, 4)
# grey heights for bump maps: two bumps and a ridge
def height(x, y):
    h = 0.5 + 0.4 * math.exp(-((x - 6) ** 2 + (y - 5) ** 2) / 8) - 0.3 * math.exp(-((x - 14) ** 2 + (y - 9) ** 2) / 6)
    return min(1, max(0, h + 0.1 * math.sin(x * 1.3)))
grey = [bytes(int(height(x, y) * 255) for x in range(W)) for y in range(H)]
png("map_grey8.png", 0, 8, grey)
# PPM (binary P6): linear values
open(os.path.join(out, "map_rgb.ppm"), "wb").write(b"P6\n%d %d\n255\n" % (W, H) + b"".join(rgb))
