-- spec/helpers/png.lua, the PNG decoder the specs use to read LÖVE screenshots. The fixtures
-- in spec/fixtures/png/ come from tools/make-png-fixtures.py; every pixel is a function of
-- (x, y) that this file computes again (the functions below are the script's), so the
-- decoder is checked against how the images were made, never against its own output.
local png = require('spec.helpers.png')
local expect = require('spec.helpers.expect')
local raisesAt = expect.raisesAt
local floor, char = math.floor, string.char

local DIR = 'spec/fixtures/png/'

local function readFile(name)
  local f = assert(io.open(DIR .. name, 'rb'))
  local s = f:read('*a')
  f:close()
  return s
end

-- Pixel functions, as in tools/make-png-fixtures.py ---------------------------------------

local function noise(x, y)
  return (x * 37 + y * 11) % 256, (x * 5 + y * 71 + 13) % 256,
    (x * x + 3 * y * y + 7 * x * y) % 256, (x * 29 + y * 3 + 100) % 256
end

local function opaqueNoise(x, y)
  local r, g, b = noise(x, y)
  return r, g, b, 255
end

local function tiles(x, y)
  return noise(floor(x / 8), floor(y / 8))
end

local function sample(x, y, mod)
  return (x * 3 + y * 5 + x * y) % mod
end

local function paletteEntry(k)
  return (k * 40) % 256, (255 - k * 17) % 256, (k * k * 7) % 256
end

local function paletteAlpha(k)
  return (k * 50 + 5) % 256
end

-- Every pixel of `image` must be want(x, y); returns how many were checked.
local function expectPixels(image, width, height, want)
  assert.are.equal(width, image.width)
  assert.are.equal(height, image.height)
  for y = 0, height - 1 do
    for x = 0, width - 1 do
      local r, g, b, a = image:pixel(x, y)
      local wr, wg, wb, wa = want(x, y)
      if r ~= wr or g ~= wg or b ~= wb or a ~= wa then
        error(('pixel (%d, %d): got %s %s %s %s, want %d %d %d %d'):format(
          x, y, tostring(r), tostring(g), tostring(b), tostring(a), wr, wg, wb, wa), 2)
      end
    end
  end
  return width * height
end

local function pixelOf(image, x, y)
  return { image:pixel(x, y) }
end

-- Building PNG and zlib bytes here ----------------------------------------------------------

local function u32(v)
  return char(floor(v / 16777216) % 256, floor(v / 65536) % 256, floor(v / 256) % 256, v % 256)
end

-- A chunk with a zero CRC: the decoder does not check CRCs.
local function chunk(kind, body)
  return u32(#body) .. kind .. body .. '\0\0\0\0'
end

local SIGNATURE = '\137PNG\r\n\26\n'

local function ihdr(width, height, depth, colourType)
  return chunk('IHDR', u32(width) .. u32(height) .. char(depth, colourType, 0, 0, 0))
end

-- A PNG of one IDAT chunk, with `extra` chunks (a string) between IHDR and IDAT.
local function pngOf(width, height, depth, colourType, idat, extra)
  return SIGNATURE .. ihdr(width, height, depth, colourType) .. (extra or '') .. chunk('IDAT', idat)
    .. chunk('IEND', '')
end

-- The chunks of a PNG file as { kind, body } pairs, and back.
local function chunksOf(s)
  local list, pos = {}, 9
  while pos <= #s do
    local b1, b2, b3, b4 = s:byte(pos, pos + 3)
    local length = ((b1 * 256 + b2) * 256 + b3) * 256 + b4
    list[#list + 1] = { s:sub(pos + 4, pos + 7), s:sub(pos + 8, pos + 7 + length) }
    pos = pos + 12 + length
  end
  return list
end

local function fromChunks(list)
  local parts = { SIGNATURE }
  for _, c in ipairs(list) do parts[#parts + 1] = chunk(c[1], c[2]) end
  return table.concat(parts)
end

-- `s` with the bytes from index i on replaced by `bytes`.
local function patch(s, i, bytes)
  return s:sub(1, i - 1) .. bytes .. s:sub(i + #bytes)
end

local function adler32(s)
  local a, b = 1, 0
  for i = 1, #s do
    a = (a + s:byte(i)) % 65521
    b = (b + a) % 65521
  end
  return b * 65536 + a
end

-- A zlib stream (header 78 01) around raw deflate data that inflates to `raw`.
local function zlibOf(deflate, raw)
  return '\120\1' .. deflate .. u32(adler32(raw))
end

-- One final stored block holding `raw`.
local function storedOf(raw)
  return char(1, #raw % 256, floor(#raw / 256), (65535 - #raw) % 256, floor((65535 - #raw) / 256)) .. raw
end

-- Deflate bits, packed least significant bit first (RFC 1951 3.1.1).
local function bitWriter()
  local bytes, acc, count = {}, 0, 0
  local POW = { 1, 2, 4, 8, 16, 32, 64, 128 }
  local w = {}
  local function put(bit)
    acc = acc + bit * POW[count + 1]
    count = count + 1
    if count == 8 then
      bytes[#bytes + 1] = char(acc)
      acc, count = 0, 0
    end
  end
  -- `value` in `n` bits, least significant first (header fields, extra bits).
  function w.bits(value, n)
    for _ = 1, n do
      local bit = value % 2
      put(bit)
      value = (value - bit) / 2
    end
    return w
  end
  -- A Huffman code of `n` bits, most significant first.
  function w.code(code, n)
    for i = n - 1, 0, -1 do put(floor(code / 2 ^ i) % 2) end
    return w
  end
  -- The fixed-Huffman code of a literal/length symbol (RFC 1951 3.2.6).
  function w.fixed(sym)
    if sym < 144 then return w.code(48 + sym, 8) end
    if sym < 256 then return w.code(400 + sym - 144, 9) end
    if sym < 280 then return w.code(sym - 256, 7) end
    return w.code(192 + sym - 280, 8)
  end
  -- A dynamic block header for literal/length code lengths lit[0..nLit-1] and distance
  -- code lengths dist[0..nDist-1]; the code length code gives symbols 0-15 4 bits each,
  -- so each length is sent as its own 4-bit code.
  function w.dynamic(final, lit, nLit, dist, nDist)
    w.bits(final, 1).bits(2, 2).bits(nLit - 257, 5).bits(nDist - 1, 5).bits(19 - 4, 4)
    for _, sym in ipairs({ 16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15 }) do
      w.bits(sym < 16 and 4 or 0, 3)
    end
    for s = 0, nLit - 1 do w.code(lit[s] or 0, 4) end
    for s = 0, nDist - 1 do w.code(dist[s] or 0, 4) end
    return w
  end
  function w.finish()
    if count > 0 then
      bytes[#bytes + 1] = char(acc)
      acc, count = 0, 0
    end
    return table.concat(bytes)
  end
  return w
end

-- Deflate blocks -----------------------------------------------------------------------------

describe('png.decode reads deflate', function()
  it('stored blocks (an RGB image in 60-byte blocks)', function()
    local image = png.decode(readFile('stored.png'))
    expectPixels(image, 13, 7, opaqueNoise)
    assert.are.same({ 133, 170, 63, 255 }, pixelOf(image, 3, 2))
    assert.are.same({ 0, 13, 0, 255 }, pixelOf(image, 0, 0))
  end)

  it('fixed Huffman blocks', function()
    local image = png.decode(readFile('fixed.png'))
    expectPixels(image, 16, 12, noise)
    assert.are.same({ 133, 170, 63, 193 }, pixelOf(image, 3, 2))
    assert.are.same({ 10, 71, 252, 30 }, pixelOf(image, 6, 4))
  end)

  it('dynamic Huffman blocks with long matches (8x8 tiles)', function()
    local image = png.decode(readFile('dynamic.png'))
    expectPixels(image, 64, 48, tiles)
    assert.are.same({ 133, 170, 63, 193 }, pixelOf(image, 3 * 8 + 7, 2 * 8))
  end)

  it('dynamic Huffman codes 15 bits long', function()
    local image = png.decode(readFile('dynamic-15bit.png'))
    local values, count, k = {}, 2, 2
    local nextCount = 3
    while #values < 4178 do
      for _ = 1, count do values[#values + 1] = 9 * k + 1 end
      count, nextCount, k = nextCount, count + nextCount, k + 1
    end
    expectPixels(image, 4178, 1, function(x) local v = values[x + 1]; return v, v, v, 255 end)
    assert.are.same({ 19, 19, 19, 255 }, pixelOf(image, 1, 0))
    assert.are.same({ 145, 145, 145, 255 }, pixelOf(image, 4177, 0))
  end)

  it('stored, fixed and dynamic blocks in one stream', function()
    expectPixels(png.decode(readFile('mixed-blocks.png')), 24, 16, noise)
  end)

  it('a zlib stream split over many IDAT chunks, one empty, among ancillary chunks', function()
    local s = readFile('multi-idat.png')
    local idats = 0
    for _, c in ipairs(chunksOf(s)) do
      if c[1] == 'IDAT' then idats = idats + 1 end
    end
    assert.is_true(idats >= 5)
    expectPixels(png.decode(s), 20, 10, noise)
  end)

  it('matches that overlap what they copy (distance 1, length 258)', function()
    -- Grey 260x1: filter byte 0, literal 9, a match of 258 at distance 1, literal 10.
    local deflate = bitWriter().bits(1, 1).bits(1, 2).fixed(0).fixed(9).fixed(285).code(0, 5)
      .fixed(10).fixed(256).finish()
    local raw = '\0\9' .. ('\9'):rep(258) .. '\10'
    local image = png.decode(pngOf(260, 1, 8, 0, zlibOf(deflate, raw)))
    expectPixels(image, 260, 1, function(x) local v = x == 259 and 10 or 9; return v, v, v, 255 end)
  end)

  it('an incomplete distance code of a single 1-bit code, as RFC 1951 allows', function()
    -- Literal/length codes 0 -> 00, 7 -> 01, 256 -> 10, 257 (length 3) -> 11; distance
    -- code 0 (distance 1) -> 0. Grey 7x1: filter 0, literal 7, two matches of 3 at distance 1.
    local deflate = bitWriter().dynamic(1, { [0] = 2, [7] = 2, [256] = 2, [257] = 2 }, 258, { [0] = 1 }, 1)
      .code(0, 2).code(1, 2).code(3, 2).code(0, 1).code(3, 2).code(0, 1).code(2, 2).finish()
    local image = png.decode(pngOf(7, 1, 8, 0, zlibOf(deflate, '\0' .. ('\7'):rep(7))))
    expectPixels(image, 7, 1, function() return 7, 7, 7, 255 end)
  end)

  it('an empty stored block before the final block', function()
    local deflate = '\0\0\0\255\255' .. storedOf('\0\1\2\3')
    local image = png.decode(pngOf(1, 1, 8, 2, zlibOf(deflate, '\0\1\2\3')))
    assert.are.same({ 1, 2, 3, 255 }, pixelOf(image, 0, 0))
  end)
end)

-- Row filters --------------------------------------------------------------------------------

describe('png.decode undoes the row filter', function()
  for _, name in ipairs({ 'none', 'sub', 'up', 'average', 'paeth' }) do
    it(name .. ' on every row, in RGB and in RGBA', function()
      expectPixels(png.decode(readFile('rgb-' .. name .. '.png')), 7, 5, opaqueNoise)
      expectPixels(png.decode(readFile('rgba-' .. name .. '.png')), 7, 5, noise)
    end)
  end

  it('Paeth breaking ties as the PNG spec says: a, then b, then c', function()
    -- Grey 4x2. Row 0 (no filter): 10 20 30 40. Row 1 (Paeth) should read 5 0 50 1:
    -- x = 0: a = 0, b = 10, c = 0, predictor b = 10, filtered 5 - 10 = 251;
    -- x = 1: a = 5, b = 20, c = 10: |p - b| = |p - c| = 5 < |p - a| = 10, so b: 0 - 20 = 236;
    -- x = 2: a = 0, b = 30, c = 20: |p - a| = |p - c| = 10 < |p - b| = 20, so a: 50 - 0 = 50;
    -- x = 3: a = 50, b = 40, c = 30: a: 1 - 50 = 207.
    local raw = '\0\10\20\30\40' .. '\4\251\236\50\207'
    local image = png.decode(pngOf(4, 2, 8, 0, zlibOf(storedOf(raw), raw)))
    local want = { [0] = { 10, 20, 30, 40 }, { 5, 0, 50, 1 } }
    expectPixels(image, 4, 2, function(x, y) local v = want[y][x + 1]; return v, v, v, 255 end)
  end)
end)

-- Colour types -------------------------------------------------------------------------------

describe('png.decode reads the colour types', function()
  it('RGBA and RGB: r, g, b, a as integers 0-255, alpha 255 without an alpha channel', function()
    local rgba = png.decode(readFile('rgba-none.png'))
    local rgb = png.decode(readFile('rgb-none.png'))
    assert.are.same({ 6, 2 }, { rgba.colourType, rgb.colourType })
    assert.are.same({ 10, 71, 252, 30 }, pixelOf(rgba, 6, 4))
    assert.are.same({ 10, 71, 252, 255 }, pixelOf(rgb, 6, 4))
    local mathType = math.type -- luacheck: ignore 143 (Lua 5.3+ only)
    if mathType then
      local grey = png.decode(readFile('grey-2bit.png'))
      for _, image in ipairs({ rgba, rgb, grey, png.decode(readFile('palette-4bit.png')) }) do
        for _, v in ipairs(pixelOf(image, 1, 2)) do assert.are.equal('integer', mathType(v)) end
      end
    end
  end)

  it('palette at 1, 2, 4 and 8 bits per index, with tRNS alpha for the first entries', function()
    for _, case in ipairs({ { 1, 13, 4, 2, 1 }, { 2, 11, 5, 4, 2 }, { 4, 9, 6, 11, 6 }, { 8, 6, 5, 200, 0 } }) do
      local depth, width, height, entries, alphas = case[1], case[2], case[3], case[4], case[5]
      local image = png.decode(readFile('palette-' .. depth .. 'bit.png'))
      assert.are.same({ 3, depth }, { image.colourType, image.bitDepth })
      expectPixels(image, width, height, function(x, y)
        local k = sample(x, y, entries)
        local r, g, b = paletteEntry(k)
        return r, g, b, k < alphas and paletteAlpha(k) or 255
      end)
    end
  end)

  it('greyscale at 1, 2, 4 and 8 bits, scaled to 0-255, with a tRNS key', function()
    for _, case in ipairs({ { 1, 11, 3 }, { 2, 9, 4 }, { 4, 7, 5 }, { 8, 10, 6 } }) do
      local depth, width, height = case[1], case[2], case[3]
      local image = png.decode(readFile('grey-' .. depth .. 'bit.png'))
      local levels = 2 ^ depth
      local key, keyed = sample(2, 1, levels), 0
      expectPixels(image, width, height, function(x, y)
        local v = sample(x, y, levels)
        if v == key then keyed = keyed + 1 end
        local grey = v * 255 / (levels - 1)
        return grey, grey, grey, v == key and 0 or 255
      end)
      assert.is_true(keyed > 0)
    end
    assert.are.same({ 255, 255, 255, 0 }, pixelOf(png.decode(readFile('grey-1bit.png')), 1, 1))
    assert.are.same({ 0, 0, 0, 255 }, pixelOf(png.decode(readFile('grey-1bit.png')), 0, 0))
    assert.are.same({ 170, 170, 170, 255 }, pixelOf(png.decode(readFile('grey-2bit.png')), 0, 2))
    assert.are.same({ 221, 221, 221, 0 }, pixelOf(png.decode(readFile('grey-4bit.png')), 2, 1))
    assert.are.same({ 13, 13, 13, 0 }, pixelOf(png.decode(readFile('grey-8bit.png')), 2, 1))
    assert.are.same({ 15, 15, 15, 255 }, pixelOf(png.decode(readFile('grey-8bit.png')), 1, 2))
  end)

  it('greyscale + alpha', function()
    expectPixels(png.decode(readFile('grey-alpha.png')), 9, 7, function(x, y)
      local r, _, _, a = noise(x, y)
      return r, r, r, a
    end)
  end)

  it('RGB with a tRNS key: that colour has alpha 0', function()
    local kr, kg, kb = noise(3, 2)
    local image = png.decode(readFile('rgb-key.png'))
    expectPixels(image, 8, 6, function(x, y)
      local r, g, b = noise(x, y)
      return r, g, b, (r == kr and g == kg and b == kb) and 0 or 255
    end)
    assert.are.same({ 133, 170, 63, 0 }, pixelOf(image, 3, 2))
  end)
end)

-- Files written by LÖVE ------------------------------------------------------------------------

describe('png.decode reads what LÖVE 11.4 writes', function()
  -- As drawn by tools/make-png-fixtures.py on a 40x30 canvas cleared to (0, 0, 0, 0), in
  -- order, blend mode 'replace': x, y, w, h, r, g, b, a.
  local RECTS = {
    { 0, 0, 20, 15, 255, 0, 0, 255 },
    { 20, 0, 19, 15, 0, 255, 0, 255 },
    { 0, 15, 20, 15, 0, 0, 255, 128 },
    { 20, 15, 19, 15, 12, 34, 56, 255 },
    { 5, 5, 3, 2, 200, 100, 50, 255 },
    { 30, 20, 4, 6, 255, 255, 255, 0 },
    { 10, 22, 1, 1, 1, 2, 3, 4 },
  }
  local function canvasPixel(x, y)
    local r, g, b, a = 0, 0, 0, 0
    for _, rect in ipairs(RECTS) do
      if x >= rect[1] and x < rect[1] + rect[3] and y >= rect[2] and y < rect[2] + rect[4] then
        r, g, b, a = rect[5], rect[6], rect[7], rect[8]
      end
    end
    return r, g, b, a
  end

  it('a canvas of flat rectangles, which LÖVE writes as a 4-bit palette with tRNS', function()
    local image = png.read(DIR .. 'love-canvas.png')
    assert.are.same({ 3, 4 }, { image.colourType, image.bitDepth })
    expectPixels(image, 40, 30, canvasPixel)
    assert.are.same({ 255, 0, 0, 255 }, pixelOf(image, 0, 0))
    assert.are.same({ 200, 100, 50, 255 }, pixelOf(image, 7, 6))
    assert.are.same({ 255, 0, 0, 255 }, pixelOf(image, 8, 6))
    assert.are.same({ 0, 255, 0, 255 }, pixelOf(image, 38, 14))
    assert.are.same({ 0, 0, 0, 0 }, pixelOf(image, 39, 14))
    assert.are.same({ 0, 0, 255, 128 }, pixelOf(image, 19, 29))
    assert.are.same({ 12, 34, 56, 255 }, pixelOf(image, 20, 15))
    assert.are.same({ 255, 255, 255, 0 }, pixelOf(image, 33, 25))
    assert.are.same({ 1, 2, 3, 4 }, pixelOf(image, 10, 22))
  end)

  it('ImageData with many colours: RGBA, and RGB when opaque', function()
    local rgba, rgb = png.read(DIR .. 'love-rgba.png'), png.read(DIR .. 'love-rgb.png')
    assert.are.same({ 6, 2 }, { rgba.colourType, rgb.colourType })
    expectPixels(rgba, 23, 17, noise)
    expectPixels(rgb, 19, 13, opaqueNoise)
  end)
end)

-- image:pixel and png.read -------------------------------------------------------------------

describe('png.Image:pixel', function()
  local image = png.decode(readFile('rgba-none.png'))

  it('takes 0-based integer coordinates inside the image', function()
    assert.are.same({ 0, 13, 0, 100 }, pixelOf(image, 0, 0))
    raisesAt(function() image:pixel(-1, 0) end, 'png.Image:pixel: (-1, 0) is not a pixel of this 7x5 image')
    raisesAt(function() image:pixel(7, 0) end, 'png.Image:pixel: (7, 0) is not a pixel of this 7x5 image')
    raisesAt(function() image:pixel(0, 5) end, 'png.Image:pixel: (0, 5) is not a pixel of this 7x5 image')
    raisesAt(function() image:pixel(0.5, 1) end, 'png.Image:pixel: (0.5, 1) is not a pixel')
    raisesAt(function() image:pixel(1) end, 'png.Image:pixel: (1, nil) is not a pixel')
  end)

  it('reports a palette index past the palette', function()
    local plte = chunk('PLTE', '\1\2\3\4\5\6')
    local bad = png.decode(pngOf(2, 1, 8, 3, zlibOf(storedOf('\0\1\2'), '\0\1\2'), plte))
    assert.are.same({ 4, 5, 6, 255 }, pixelOf(bad, 0, 0))
    raisesAt(function() bad:pixel(1, 0) end, 'png.Image:pixel: (1, 0) has palette index 2, past the 2 palette entries')
  end)
end)

describe('png.read', function()
  it('reads a file in binary mode and decodes it', function()
    expectPixels(png.read(DIR .. 'fixed.png'), 16, 12, noise)
  end)

  it('names the file it cannot open or decode', function()
    raisesAt(function() png.read(DIR .. 'missing.png') end, 'png.read: cannot open ' .. DIR .. 'missing.png')
    raisesAt(function() png.read('spec/png_spec.lua') end,
      'png.read: spec/png_spec.lua: png.decode: not a PNG file (bad signature)')
  end)
end)

-- Errors -------------------------------------------------------------------------------------

describe('png.decode rejects', function()
  local good = readFile('rgba-none.png') -- IHDR data at bytes 17-29: width, height, depth, ...
  local DEPTH, COLOUR, COMPRESSION, FILTER, INTERLACE = 25, 26, 27, 28, 29

  -- `good` with its IDAT data replaced.
  local function withIdat(data)
    local list = chunksOf(good)
    for _, c in ipairs(list) do
      if c[1] == 'IDAT' then c[2] = data end
    end
    return fromChunks(list)
  end
  local goodIdat
  for _, c in ipairs(chunksOf(good)) do
    if c[1] == 'IDAT' then goodIdat = c[2] end
  end
  local rawSize = 5 * (7 * 4 + 1)

  -- A one-pixel RGB PNG around deflate data (zlib header and Adler-32 of `raw` added).
  local function pixelPng(deflate, raw)
    return pngOf(1, 1, 8, 2, zlibOf(deflate, raw or '\0\1\2\3'))
  end

  it('what is not a string', function()
    raisesAt(function() png.decode(nil) end, 'png.decode: expected the bytes of a PNG file as a string, got nil')
    raisesAt(function() png.decode(42) end, 'png.decode: expected the bytes of a PNG file as a string, got number')
  end)

  it('a bad signature', function()
    raisesAt(function() png.decode(patch(good, 2, 'Q')) end, 'png.decode: not a PNG file (bad signature)')
    raisesAt(function() png.decode('') end, 'png.decode: not a PNG file (0 bytes, shorter than the signature)')
    raisesAt(function() png.decode(good:sub(1, 5)) end, 'png.decode: not a PNG file (5 bytes')
  end)

  it('a truncated file', function()
    raisesAt(function() png.decode(good:sub(1, 8)) end, 'png.decode: truncated data (file ends at byte 8')
    raisesAt(function() png.decode(good:sub(1, 20)) end, 'png.decode: truncated data (IHDR chunk of 13 bytes')
    raisesAt(function() png.decode(good:sub(1, #good - 40)) end, 'png.decode: truncated data (IDAT chunk')
    raisesAt(function() png.decode(good:sub(1, #good - 12)) end, 'png.decode: truncated data (file ends at byte')
    raisesAt(function() png.decode(good:sub(1, #good - 1)) end, 'png.decode: truncated data (IEND chunk')
  end)

  it('an unsupported or bad bit depth', function()
    raisesAt(function() png.decode(patch(good, DEPTH, '\16')) end,
      'png.decode: unsupported bit depth 16 (only 1, 2, 4 and 8)')
    raisesAt(function() png.decode(patch(good, DEPTH, '\4')) end,
      'png.decode: bad bit depth 4 for colour type 6 (RGBA allows 8 16)')
    raisesAt(function() png.decode(patch(good, DEPTH, '\3')) end, 'png.decode: bad bit depth 3 for colour type 6')
  end)

  it('a bad colour type', function()
    raisesAt(function() png.decode(patch(good, COLOUR, '\5')) end, 'png.decode: bad colour type 5')
    raisesAt(function() png.decode(patch(good, COLOUR, '\1')) end, 'png.decode: bad colour type 1')
  end)

  it('interlacing, other compression or filter methods, an empty image', function()
    raisesAt(function() png.decode(patch(good, INTERLACE, '\1')) end,
      'png.decode: unsupported interlace method 1 (only 0 = none)')
    raisesAt(function() png.decode(patch(good, COMPRESSION, '\1')) end,
      'png.decode: unsupported compression method 1 (only 0)')
    raisesAt(function() png.decode(patch(good, FILTER, '\1')) end, 'png.decode: unsupported filter method 1 (only 0)')
    raisesAt(function() png.decode(patch(good, 17, u32(0))) end, 'png.decode: bad image size 0x5')
    raisesAt(function() png.decode(patch(good, 21, u32(0))) end, 'png.decode: bad image size 7x0')
  end)

  it('bad chunks', function()
    local list = chunksOf(good)
    raisesAt(function() png.decode(SIGNATURE .. chunk('tEXt', 'a\0b') .. good:sub(9)) end,
      'png.decode: first chunk is "tEXt", not IHDR')
    raisesAt(function() png.decode(SIGNATURE .. chunk('IHDR', list[1][2]:sub(1, 12)) .. good:sub(34)) end,
      'png.decode: IHDR chunk of 12 bytes, not 13')
    raisesAt(function() png.decode(SIGNATURE .. ihdr(7, 5, 8, 6) .. good:sub(9)) end, 'png.decode: second IHDR chunk')
    raisesAt(function() png.decode(fromChunks({ list[1], { 'IEND', '' } })) end, 'png.decode: no IDAT chunk')
    local unknown = fromChunks({ list[1], list[2], { 'ABCD', 'x' }, { 'IEND', '' } })
    raisesAt(function() png.decode(unknown) end, 'png.decode: unsupported critical chunk "ABCD"')
    -- (an unknown ancillary chunk is skipped)
    expectPixels(png.decode(fromChunks({ list[1], { 'abCD', 'x' }, list[2], { 'IEND', '' } })), 7, 5, noise)
  end)

  it('bad palettes and transparency', function()
    local idat = zlibOf(storedOf('\0\0'), '\0\0')
    raisesAt(function() png.decode(pngOf(1, 1, 8, 3, idat)) end, 'png.decode: palette image without a PLTE chunk')
    raisesAt(function() png.decode(pngOf(1, 1, 8, 3, idat, chunk('PLTE', '\1\2'))) end,
      'png.decode: PLTE chunk of 2 bytes')
    raisesAt(function() png.decode(pngOf(1, 1, 8, 3, idat, chunk('tRNS', '\1'))) end,
      'png.decode: tRNS chunk before PLTE')
    raisesAt(function() png.decode(pngOf(1, 1, 8, 3, idat, chunk('PLTE', '\1\2\3') .. chunk('tRNS', '\1\2'))) end,
      'png.decode: tRNS chunk of 2 alpha values for 1 palette entries')
    raisesAt(function() png.decode(pngOf(1, 1, 8, 0, idat, chunk('tRNS', '\1'))) end,
      'png.decode: tRNS chunk of 1 bytes for colour type 0')
  end)

  it('a bad zlib header', function()
    local cmf, flg = goodIdat:byte(1, 2)
    raisesAt(function() png.decode(withIdat(char(cmf, flg + 1) .. goodIdat:sub(3))) end,
      'png.decode: bad zlib header (check bits)')
    raisesAt(function() png.decode(withIdat('\119\9' .. goodIdat:sub(3))) end,
      'png.decode: bad zlib header (compression method 7, not 8 = deflate)')
    raisesAt(function() png.decode(withIdat('\136\28' .. goodIdat:sub(3))) end,
      'png.decode: bad zlib header (window size 2^16)')
    raisesAt(function() png.decode(withIdat('\120\32' .. goodIdat:sub(3))) end,
      'png.decode: bad zlib header (preset dictionary not supported)')
    raisesAt(function() png.decode(withIdat('\120')) end, 'png.decode: truncated zlib data (1 bytes)')
  end)

  it('truncated or corrupt zlib data', function()
    local fixed = readFile('fixed.png') -- (Huffman-coded, where rgba-none.png has a stored block)
    local list = chunksOf(fixed)
    list[2][2] = list[2][2]:sub(1, 300)
    raisesAt(function() png.decode(fromChunks(list)) end, 'png.decode: truncated zlib data')
    raisesAt(function() png.decode(withIdat(goodIdat:sub(1, 40))) end, 'png.decode: truncated zlib data')
    raisesAt(function() png.decode(withIdat(goodIdat:sub(1, #goodIdat - 4))) end, 'png.decode: truncated zlib data')
    local last = goodIdat:byte(#goodIdat)
    raisesAt(function() png.decode(withIdat(patch(goodIdat, #goodIdat, char((last + 1) % 256)))) end,
      'png.decode: bad zlib Adler-32 checksum')
  end)

  it('bad stored blocks', function()
    raisesAt(function() png.decode(pixelPng('\1\4\0\250\255\0\1\2\3')) end,
      'png.decode: bad stored block length (LEN 4, NLEN 65530)')
    raisesAt(function() png.decode(pngOf(1, 1, 8, 2, '\120\1\1\4\0\251\255\0\1')) end,
      'png.decode: truncated zlib data (stored block of 4 bytes)')
    raisesAt(function() png.decode(pngOf(1, 1, 8, 2, '\120\1\1\4\0')) end,
      'png.decode: truncated zlib data (stored block header)')
  end)

  it('a bad block type', function()
    raisesAt(function() png.decode(pixelPng(bitWriter().bits(1, 1).bits(3, 2).finish())) end,
      'png.decode: bad deflate block type 3')
  end)

  it('bad Huffman codes', function()
    -- Literal/length code 0 -> 0, 256 -> 10; 11 is no code.
    local w = bitWriter().dynamic(1, { [0] = 1, [256] = 2 }, 257, {}, 1).code(0, 1).code(3, 2)
    raisesAt(function() png.decode(pixelPng(w.finish())) end, 'png.decode: bad Huffman code (literal/length)')
    w = bitWriter().dynamic(1, { [0] = 1, [1] = 1, [256] = 1 }, 257, {}, 1)
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: bad Huffman code: over-subscribed literal/length code lengths')
    w = bitWriter().dynamic(1, { [0] = 1, [256] = 1 }, 257, { [0] = 1, [1] = 1, [2] = 1 }, 3)
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: bad Huffman code: over-subscribed distance code lengths')
    -- The code length code: three 1-bit codes (for 16, 17, 18).
    w = bitWriter().bits(1, 1).bits(2, 2).bits(0, 5).bits(0, 5).bits(0, 4).bits(1, 3).bits(1, 3).bits(1, 3).bits(0, 3)
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: bad Huffman code: over-subscribed code length code lengths')
    -- A distance code that is not there: literal/length 0 -> 0, 256 -> 10, 257 -> 11; the
    -- distance code has only 0 -> 0.
    w = bitWriter().dynamic(1, { [0] = 1, [256] = 2, [257] = 2 }, 258, { [0] = 1 }, 1)
    w.code(0, 1).code(0, 1).code(3, 2).code(1, 1) -- literal 0, literal 0, length 3, distance "1"
    raisesAt(function() png.decode(pixelPng(w.finish())) end, 'png.decode: bad Huffman code (distance)')
  end)

  it('bad code lengths in a dynamic block header', function()
    -- Too many literal/length or distance codes.
    local w = bitWriter().bits(1, 1).bits(2, 2).bits(30, 5).bits(0, 5).bits(0, 4)
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: bad dynamic block header (287 literal/length codes)')
    w = bitWriter().bits(1, 1).bits(2, 2).bits(0, 5).bits(30, 5).bits(0, 4)
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: bad dynamic block header (31 distance codes)')
    -- Code length code 0 -> 0, 16 -> 1 (16, 17, 18, 0 are the first four sent); 16 first.
    w = bitWriter().bits(1, 1).bits(2, 2).bits(0, 5).bits(0, 5).bits(0, 4).bits(1, 3).bits(0, 3).bits(0, 3)
      .bits(1, 3).code(1, 1)
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: bad code lengths (repeat with no previous length)')
    -- Code length code 0 -> 0, 18 -> 1; two runs of 138 zeros for 258 lengths.
    w = bitWriter().bits(1, 1).bits(2, 2).bits(0, 5).bits(0, 5).bits(0, 4).bits(0, 3).bits(0, 3).bits(1, 3)
      .bits(1, 3).code(1, 1).bits(127, 7).code(1, 1).bits(127, 7)
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: bad code lengths (repeat past the last code)')
    w = bitWriter().dynamic(1, { [0] = 1, [1] = 1 }, 257, {}, 1)
    raisesAt(function() png.decode(pixelPng(w.finish())) end, 'png.decode: bad code lengths (no end-of-block code)')
  end)

  it('bad lengths and distances', function()
    local w = bitWriter().bits(1, 1).bits(1, 2).fixed(0).fixed(286)
    raisesAt(function() png.decode(pixelPng(w.finish())) end, 'png.decode: bad length code 286')
    w = bitWriter().bits(1, 1).bits(1, 2).fixed(0).fixed(257).code(30, 5)
    raisesAt(function() png.decode(pixelPng(w.finish())) end, 'png.decode: bad distance code 30')
    w = bitWriter().bits(1, 1).bits(1, 2).fixed(0).fixed(257).code(1, 5) -- distance 2
    raisesAt(function() png.decode(pixelPng(w.finish())) end, 'png.decode: bad distance 2 (only 1 bytes so far)')
  end)

  it('the wrong decompressed size', function()
    raisesAt(function() png.decode(pixelPng(storedOf('\0\1\2'), '\0\1\2')) end,
      'png.decode: wrong decompressed size (3 bytes, expected 4)')
    raisesAt(function() png.decode(pixelPng(storedOf('\0\1\2\3\4'), '\0\1\2\3\4')) end,
      'png.decode: wrong decompressed size (more than the 4 bytes expected)')
    local w = bitWriter().bits(1, 1).bits(1, 2).fixed(0).fixed(1).fixed(2).fixed(3).fixed(4)
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: wrong decompressed size (more than the 4 bytes expected)')
    w = bitWriter().bits(1, 1).bits(1, 2).fixed(0).fixed(258).code(0, 5) -- 1 + a match of 4
    raisesAt(function() png.decode(pixelPng(w.finish())) end,
      'png.decode: wrong decompressed size (more than the 4 bytes expected)')
    local raw = ('\0'):rep(rawSize - 1)
    raisesAt(function() png.decode(withIdat(zlibOf(storedOf(raw), raw))) end,
      'png.decode: wrong decompressed size (144 bytes, expected 145)')
  end)

  it('a bad filter type', function()
    raisesAt(function() png.decode(pixelPng(storedOf('\5\1\2\3'), '\5\1\2\3')) end,
      'png.decode: bad filter type 5 on row 0')
  end)
end)
