# Writes the small height_field probe images (pure Python: zlib + struct).
import math, struct, sys, os
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from png_writer import chunk, write_png
out = sys.argv[1]
W, H = 24, 18
def height(x, y):  # 0..1, a couple of bumps and a ridge, uneven on purpose
    u, v = x / (W - 1), y / (H - 1)
    h = 0.35 + 0.3 * math.exp(-((u - 0.3) ** 2 + (v - 0.35) ** 2) * 18)
    h += 0.25 * math.exp(-((u - 0.75) ** 2 + (v - 0.7) ** 2) * 30)
    h += 0.08 * math.sin(u * 11 + v * 3)
    return min(1, max(0, h))
def png(name, colour_type, depth, rows, extra=b""):
    write_png(os.path.join(out, name), W, H, colour_type, depth, rows, extra)
g8 = [bytes(int(height(x, y) * 255) for x in range(W)) for y in range(H)]
png("hf_grey8.png", 0, 8, g8)
g16 = [b"".join(struct.pack(">H", int(height(x, y) * 65535)) for x in range(W)) for y in range(H)]
png("hf_grey16.png", 0, 16, g16)
# RGB 8-bit: red the high byte, green the low byte of the 16-bit height; blue unused
rgb = []
for y in range(H):
    r = b""
    for x in range(W):
        v = int(height(x, y) * 65535)
        r += bytes([v >> 8, v & 255, 77])
    rgb.append(r)
png("hf_rgb8.png", 2, 8, rgb)
# palette: 16 entries (colours unrelated to the index), heights = index * 256
plte = b"".join(bytes([(i * 53) % 256, (i * 97) % 256, (255 - i * 16) % 256]) for i in range(16))
pal = [bytes(min(15, int(height(x, y) * 16)) for x in range(W)) for y in range(H)]
png("hf_palette.png", 3, 8, pal, chunk(b"PLTE", plte))
# PGM (binary, maxval 255) and PPM (ASCII P3, maxval 255)
open(os.path.join(out, "hf_grey.pgm"), "wb").write(b"P5\n# probe\n%d %d\n255\n" % (W, H) + b"".join(g8))
ppm = "P3\n%d %d\n255\n" % (W, H)
for row in rgb:
    ppm += " ".join(str(b) for b in row) + "\n"
open(os.path.join(out, "hf_rgb.ppm"), "w").write(ppm)
# TGA: grey (type 3, bottom-up) and RLE true colour (type 10, top-down)
hdr = struct.pack("<BBBHHBHHHHBB", 0, 0, 3, 0, 0, 0, 0, 0, W, H, 8, 0)
open(os.path.join(out, "hf_grey.tga"), "wb").write(hdr + b"".join(reversed(g8)))
def rle(pixels):  # pixels: list of bytes objects (BGR)
    out, i = b"", 0
    while i < len(pixels):
        j = i
        while j + 1 < len(pixels) and pixels[j + 1] == pixels[i] and j - i < 127: j += 1
        if j > i:
            out += bytes([128 | (j - i)]) + pixels[i]; i = j + 1
        else:
            k = i
            while k + 1 < len(pixels) and pixels[k + 1] != pixels[k] and k - i < 127: k += 1
            out += bytes([k - i]) + b"".join(pixels[i:k + 1]); i = k + 1
    return out
px = []
for row in rgb:
    for x in range(W):
        r, g, b = row[3 * x], row[3 * x + 1], row[3 * x + 2]
        px.append(bytes([b, g, r]))
hdr = struct.pack("<BBBHHBHHHHBB", 0, 0, 10, 0, 0, 0, 0, 0, W, H, 24, 0x20)
open(os.path.join(out, "hf_rgb_rle.tga"), "wb").write(hdr + rle(px))
