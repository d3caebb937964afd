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
# grey heights for bump maps: two bumps and a ridge
def height(x, y):
    h = 0.5 + 0.4 * math.exp(-((x - 6) ** 2 + (y - 5) ** 2) / 8) - 0.3 * math.exp(-((x - 14) ** 2 + (y - 9) ** 2) / 6)
    return min(1, max(0, h + 0.1 * math.sin(x * 1.3)))
grey = [bytes(int(height(x, y) * 255) for x in range(W)) for y in range(H)]
png("map_grey8.png", 0, 8, grey)
# PPM (binary P6): linear values
open(os.path.join(out, "map_rgb.ppm"), "wb").write(b"P6\n%d %d\n255\n" % (W, H) + b"".join(rgb))
