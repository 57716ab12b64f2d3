#!/usr/bin/env python3
"""Regenerate the PNG fixtures of spec/png_spec.lua in spec/fixtures/png/.

Only for regenerating the fixtures: the tests never run this script, they read the
committed files. Run it from anywhere:

    python3 tools/make-png-fixtures.py            # every fixture
    python3 tools/make-png-fixtures.py --no-love  # skip the love-*.png ones

Needs Python 3 with zlib. The love-*.png fixtures are written by LOVE 11.4's own PNG encoder
(`ImageData:encode('png')`, lodepng), from a tiny game this script writes to a temporary
folder and runs with `xvfb-run -a love <folder> ...` (both must be installed).

Every pixel value is a function of (x, y) that spec/png_spec.lua computes again (the
functions below and the ones in the spec must stay the same), so the spec checks the
decoder against how the images were made, not against its own output.

The synthetic fixtures are written by hand here, chunk by chunk, so each one exercises one
thing: the deflate block types (stored blocks written by hand, fixed Huffman with zlib's
Z_FIXED strategy, dynamic Huffman, the three in one stream), each of the five row filters
in RGB and in RGBA, the image split over many IDAT chunks, and the other colour types LOVE's
encoder picks for screenshots (palette with tRNS at bit depths 1, 2, 4 and 8, greyscale at 1,
2, 4 and 8 with a tRNS key, greyscale + alpha, RGB with a tRNS key).
"""
import os
import shutil
import struct
import subprocess
import sys
import tempfile
import zlib

OUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'spec', 'fixtures', 'png')

NONE, SUB, UP, AVERAGE, PAETH = 0, 1, 2, 3, 4
FILTER_NAMES = ['none', 'sub', 'up', 'average', 'paeth']


# --- Pixel functions (the same in spec/png_spec.lua) ---------------------------------------

def noise(x, y):
    """RGBA noise: every channel changes at every step, so the filters are all exercised."""
    return ((x * 37 + y * 11) % 256, (x * 5 + y * 71 + 13) % 256,
            (x * x + 3 * y * y + 7 * x * y) % 256, (x * 29 + y * 3 + 100) % 256)


def tiles(x, y):
    """8x8 tiles of one colour each (long runs: dynamic Huffman with long matches)."""
    return noise(x // 8, y // 8)


def sample(x, y, mod):
    """A palette index or grey sample in 0..mod-1."""
    return (x * 3 + y * 5 + x * y) % mod


def long_codes(n):
    """n grey samples: 19 twice, 28 3 times, 37 5 times, 46 8 times, ...: the value 9k + 1,
    for k = 2, 3, ..., as often as the Fibonacci number F(k + 1)."""
    values, a, b, k = [], 2, 3, 2
    while len(values) < n:
        values += [9 * k + 1] * a
        a, b, k = b, a + b, k + 1
    return values[:n]


def palette_entry(k):
    """Palette entry k as RGB; with a tRNS chunk of n values, entries k < n have alpha
    palette_alpha(k), the others 255."""
    return ((k * 40) % 256, (255 - k * 17) % 256, (k * k * 7) % 256)


def palette_alpha(k):
    return (k * 50 + 5) % 256


# --- PNG writing -------------------------------------------------------------------------

def chunk(kind, body):
    return struct.pack('>I', len(body)) + kind + body + struct.pack('>I', zlib.crc32(kind + body))


def ihdr(width, height, depth, colour_type):
    return chunk(b'IHDR', struct.pack('>IIBBBBB', width, height, depth, colour_type, 0, 0, 0))


def png_file(header, idats, extra=()):
    """Signature, IHDR, the extra (already built) chunks, the IDAT chunks, IEND."""
    return b'\x89PNG\r\n\x1a\n' + header + b''.join(extra) + b''.join(
        chunk(b'IDAT', part) for part in idats) + chunk(b'IEND', b'')


def pack_rows(width, height, depth, samples_of):
    """Rows of packed samples (no filter bytes): samples_of(x, y) -> tuple of samples."""
    rows = []
    for y in range(height):
        if depth == 8:
            rows.append(bytes(v for x in range(width) for v in samples_of(x, y)))
        else:  # one sample per pixel, packed from the high bits
            bits = ''.join(format(samples_of(x, y)[0], '0%db' % depth) for x in range(width))
            bits += '0' * (-len(bits) % 8)
            rows.append(bytes(int(bits[i:i + 8], 2) for i in range(0, len(bits), 8)))
    return rows


def paeth(a, b, c):
    p = a + b - c
    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
    if pa <= pb and pa <= pc:
        return a
    return b if pb <= pc else c


def filter_rows(rows, bpp, filters):
    """Filter each row with filters[y] and prefix its filter-type byte."""
    out = bytearray()
    prev = bytes(len(rows[0]))
    for y, row in enumerate(rows):
        f = filters[y]
        out.append(f)
        for i, v in enumerate(row):
            a = row[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            pred = [0, a, b, (a + b) // 2, paeth(a, b, c)][f]
            out.append((v - pred) % 256)
        prev = row
    return bytes(out)


def zlib_wrap(deflate, raw):
    """A zlib stream around raw deflate data (RFC 1950: header 78 01, Adler-32 at the end)."""
    return b'\x78\x01' + deflate + struct.pack('>I', zlib.adler32(raw))


def stored_blocks(raw, size, final=True):
    """Raw deflate made of stored blocks of `size` bytes."""
    out = bytearray()
    parts = [raw[i:i + size] for i in range(0, len(raw), size)] or [b'']
    for n, part in enumerate(parts):
        last = final and n == len(parts) - 1
        out += bytes([1 if last else 0]) + struct.pack('<HH', len(part), 0xFFFF ^ len(part)) + part
    return bytes(out)


def raw_deflate(raw, strategy=zlib.Z_DEFAULT_STRATEGY, flush=zlib.Z_FINISH):
    c = zlib.compressobj(9, zlib.DEFLATED, -15, 9, strategy)
    return c.compress(raw) + c.flush(flush)


def first_block_type(deflate):
    return (deflate[0] >> 1) & 3


def rgba_rows(width, height, fn, channels):
    return pack_rows(width, height, 8, lambda x, y: fn(x, y)[:channels])


def cycle(height):
    return [y % 5 for y in range(height)]


# --- The fixtures ------------------------------------------------------------------------

def synthetic():
    files = {}

    # Deflate block types.
    w, h = 13, 7
    raw = filter_rows(rgba_rows(w, h, noise, 3), 3, [NONE] * h)
    files['stored.png'] = png_file(ihdr(w, h, 8, 2), [zlib_wrap(stored_blocks(raw, 60), raw)])

    w, h = 16, 12
    raw = filter_rows(rgba_rows(w, h, noise, 4), 4, cycle(h))
    deflate = raw_deflate(raw, zlib.Z_FIXED)
    assert first_block_type(deflate) == 1
    files['fixed.png'] = png_file(ihdr(w, h, 8, 6), [zlib_wrap(deflate, raw)])

    w, h = 64, 48
    raw = filter_rows(rgba_rows(w, h, tiles, 4), 4, cycle(h))
    deflate = raw_deflate(raw)
    assert first_block_type(deflate) == 2
    files['dynamic.png'] = png_file(ihdr(w, h, 8, 6), [zlib_wrap(deflate, raw)])

    # A dynamic block with 15-bit codes (the longest): symbol counts that follow the
    # Fibonacci numbers give the deepest Huffman tree, which zlib cuts down to 15 bits. The
    # end-of-block code and the one filter-type byte (a literal 0) are the two counts of 1,
    # then the samples: 2 of one value, 3 of the next, 5, 8, ..., 1597 of the fifteenth
    # (4178 in all, one row). Huffman coding only (no matches), so the order of the samples does not matter.
    w, h = 4178, 1
    values = long_codes(w)
    raw = filter_rows(pack_rows(w, h, 8, lambda x, y: (values[x],)), 1, [NONE])
    c = zlib.compressobj(9, zlib.DEFLATED, 15, 9, zlib.Z_HUFFMAN_ONLY)
    deflate = c.compress(raw) + c.flush()
    assert first_block_type(deflate[2:]) == 2
    files['dynamic-15bit.png'] = png_file(ihdr(w, h, 8, 0), [deflate])

    # Stored, then fixed, then dynamic blocks in one stream (each part compressed alone, so
    # no match reaches back into an earlier part; a sync flush ends the fixed part on a
    # byte boundary with an empty stored block).
    w, h = 24, 16
    raw = filter_rows(rgba_rows(w, h, noise, 4), 4, cycle(h))
    third = len(raw) // 3
    fixed = raw_deflate(raw[third:2 * third], zlib.Z_FIXED, zlib.Z_SYNC_FLUSH)
    dynamic = raw_deflate(raw[2 * third:])
    assert first_block_type(fixed) == 1 and first_block_type(dynamic) == 2
    deflate = stored_blocks(raw[:third], 1000, final=False) + fixed + dynamic
    files['mixed-blocks.png'] = png_file(ihdr(w, h, 8, 6), [zlib_wrap(deflate, raw)])

    # Each filter on every row, in RGB and in RGBA.
    for f, name in enumerate(FILTER_NAMES):
        for channels, colour_type, prefix in ((3, 2, 'rgb'), (4, 6, 'rgba')):
            w, h = 7, 5
            raw = filter_rows(rgba_rows(w, h, noise, channels), channels, [f] * h)
            files['%s-%s.png' % (prefix, name)] = png_file(
                ihdr(w, h, 8, colour_type), [zlib.compress(raw, 9)])

    # Many IDAT chunks (one empty), with ancillary chunks before and after them.
    w, h = 20, 10
    raw = filter_rows(rgba_rows(w, h, noise, 4), 4, cycle(h))
    z = zlib.compress(raw, 9)
    parts = [z[:1], z[1:18], b'', z[18:40]] + [z[i:i + 50] for i in range(40, len(z), 50)]
    text = chunk(b'tEXt', b'Comment\x00split over %d IDAT chunks' % len(parts))
    data = png_file(ihdr(w, h, 8, 6), parts, [text])
    files['multi-idat.png'] = data[:-12] + chunk(b'tIME', bytes(7)) + data[-12:]

    # Palette images: 1, 2, 4 and 8 bits per index, widths that leave a partial last byte.
    for depth, w, h, entries, alphas in ((1, 13, 4, 2, 1), (2, 11, 5, 4, 2), (4, 9, 6, 11, 6),
                                         (8, 6, 5, 200, 0)):
        raw = filter_rows(pack_rows(w, h, depth, lambda x, y: (sample(x, y, entries),)), 1, cycle(h))
        plte = chunk(b'PLTE', b''.join(bytes(palette_entry(k)) for k in range(entries)))
        extra = [plte] + ([chunk(b'tRNS', bytes(palette_alpha(k) for k in range(alphas)))] if alphas else [])
        files['palette-%dbit.png' % depth] = png_file(ihdr(w, h, depth, 3), [zlib.compress(raw, 9)], extra)

    # Greyscale at 1, 2, 4 and 8 bits, each with a tRNS key (the sample of pixel (2, 1): that
    # grey has alpha 0); greyscale + alpha; RGB with a tRNS key (the colour of pixel (3, 2)).
    for depth, w, h in ((1, 11, 3), (2, 9, 4), (4, 7, 5), (8, 10, 6)):
        raw = filter_rows(pack_rows(w, h, depth, lambda x, y: (sample(x, y, 1 << depth),)), 1, cycle(h))
        files['grey-%dbit.png' % depth] = png_file(
            ihdr(w, h, depth, 0), [zlib.compress(raw, 9)],
            [chunk(b'tRNS', struct.pack('>H', sample(2, 1, 1 << depth)))])
    w, h = 9, 7
    raw = filter_rows(pack_rows(w, h, 8, lambda x, y: noise(x, y)[0:4:3]), 2, cycle(h))
    files['grey-alpha.png'] = png_file(ihdr(w, h, 8, 4), [zlib.compress(raw, 9)])
    w, h = 8, 6
    raw = filter_rows(rgba_rows(w, h, noise, 3), 3, cycle(h))
    key = struct.pack('>HHH', *noise(3, 2)[:3])
    files['rgb-key.png'] = png_file(ihdr(w, h, 8, 2), [zlib.compress(raw, 9)], [chunk(b'tRNS', key)])
    return files


# --- LOVE-written fixtures ----------------------------------------------------------------

LOVE_CONF = '''function love.conf(t)
  t.window.width, t.window.height, t.window.title = 64, 64, 'png fixtures'
  t.modules.audio, t.modules.sound, t.modules.joystick, t.modules.physics = false, false, false, false
end
'''

# The rectangles of love-canvas.png, drawn in order with blend mode 'replace' (premultiplied:
# colours stored as given) on a 40x30 canvas cleared to (0, 0, 0, 0): x, y, w, h, r, g, b, a.
# spec/png_spec.lua has the same list.
LOVE_MAIN = '''local RECTS = {
  { 0, 0, 20, 15, 255, 0, 0, 255 },
  { 20, 0, 19, 15, 0, 255, 0, 255 },
  { 0, 15, 20, 15, 0, 0, 255, 128 },
  { 20, 15, 19, 15, 12, 34, 56, 255 },
  { 5, 5, 3, 2, 200, 100, 50, 255 },
  { 30, 20, 4, 6, 255, 255, 255, 0 },
  { 10, 22, 1, 1, 1, 2, 3, 4 },
}

local function noise(x, y)
  return (x * 37 + y * 11) % 256, (x * 5 + y * 71 + 13) % 256,
    (x * x + 3 * y * y + 7 * x * y) % 256, (x * 29 + y * 3 + 100) % 256
end

local function write(path, imageData)
  local f = assert(io.open(path, 'wb'))
  f:write(imageData:encode('png'):getString())
  f:close()
end

function love.load(args)
  local dir, g = args[1], love.graphics
  local canvas = g.newCanvas(40, 30)
  g.setCanvas(canvas)
  g.clear(0, 0, 0, 0)
  g.setBlendMode('replace', 'premultiplied')
  for _, r in ipairs(RECTS) do
    g.setColor(r[5] / 255, r[6] / 255, r[7] / 255, r[8] / 255)
    g.rectangle('fill', r[1], r[2], r[3], r[4])
  end
  g.setCanvas()
  write(dir .. '/love-canvas.png', canvas:newImageData())

  -- ImageData written directly: noise with alpha (RGBA) and opaque (RGB).
  for _, opaque in ipairs({ false, true }) do
    local data = love.image.newImageData(opaque and 19 or 23, opaque and 13 or 17)
    data:mapPixel(function(x, y)
      local r, gr, b, a = noise(x, y)
      return r / 255, gr / 255, b / 255, opaque and 1 or a / 255
    end)
    write(dir .. (opaque and '/love-rgb.png' or '/love-rgba.png'), data)
  end
  love.event.quit()
end
'''


def love_fixtures():
    for tool in ('love', 'xvfb-run'):
        if not shutil.which(tool):
            sys.exit('%s not found: install it, or pass --no-love' % tool)
    game, out = tempfile.mkdtemp(), tempfile.mkdtemp()
    try:
        for name, text in (('conf.lua', LOVE_CONF), ('main.lua', LOVE_MAIN)):
            with open(os.path.join(game, name), 'w') as f:
                f.write(text)
        subprocess.run(['xvfb-run', '-a', 'love', game, out], check=True)
        files = {}
        for name in ('love-canvas.png', 'love-rgba.png', 'love-rgb.png'):
            with open(os.path.join(out, name), 'rb') as f:
                files[name] = f.read()
        return files
    finally:
        shutil.rmtree(game)
        shutil.rmtree(out)


def main():
    files = synthetic()
    if '--no-love' not in sys.argv[1:]:
        files.update(love_fixtures())
    os.makedirs(OUT, exist_ok=True)
    for name, data in sorted(files.items()):
        with open(os.path.join(OUT, name), 'wb') as f:
            f.write(data)
        print('%6d  %s' % (len(data), os.path.relpath(os.path.join(OUT, name))))
    print('%6d  total' % sum(len(d) for d in files.values()))


if __name__ == '__main__':
    main()
