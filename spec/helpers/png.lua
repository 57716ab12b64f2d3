--- A small PNG decoder for the specs: it reads the screenshots LÖVE 11 writes
--- (`Canvas:newImageData():encode('png')`) so a spec can check pixel colours.
---
--- LÖVE 11.4 encodes with lodepng, which writes the smallest lossless colour type for the
--- pixels it is given: a flat-coloured screenshot usually comes out as a palette image (with
--- a tRNS chunk for alpha) of bit depth 1, 2, 4 or 8, an opaque one as RGB, greys as
--- greyscale. So every non-interlaced colour type is read, at bit depths up to 8: greyscale
--- (0), RGB (2), palette (3), greyscale + alpha (4), RGBA (6), with tRNS transparency. Not
--- read: 16-bit samples and Adam7 interlacing (LÖVE writes neither).
---
--- Inflate is its own, written from RFC 1950 (zlib wrapper) and RFC 1951 (stored, fixed and
--- dynamic Huffman blocks) with arithmetic only (no bitwise operators, no bit library), so
--- it runs unchanged on Lua 5.1, 5.2, 5.3, 5.4 and LuaJIT. Huffman codes are decoded with
--- one lookup table per code, indexed by the next `maxLength` bits of the stream (least
--- significant bit first, as RFC 1951 packs them). The zlib Adler-32 is checked; the PNG
--- chunk CRCs are not.
local png = {}

local byte, sub, concat, format = string.byte, string.sub, table.concat, string.format
local floor, type, error, pcall, setmetatable, getmetatable = math.floor, type, error, pcall, setmetatable, getmetatable

local SIGNATURE = '\137PNG\r\n\26\n'
-- Samples per pixel, and the bit depths allowed (PNG spec 11.2.2), by colour type.
local CHANNELS = { [0] = 1, [2] = 3, [3] = 1, [4] = 2, [6] = 4 }
local DEPTHS = { [0] = '1 2 4 8 16', [2] = '8 16', [3] = '1 2 4 8', [4] = '8 16', [6] = '8 16' }
local COLOUR_NAMES = { [0] = 'greyscale', [2] = 'RGB', [3] = 'palette', [4] = 'greyscale + alpha', [6] = 'RGBA' }

-- POW2[k] = 2^k, built by multiplication so it is an integer on Lua 5.3+.
local POW2 = { [0] = 1 }
for k = 1, 32 do POW2[k] = POW2[k - 1] * 2 end

-- Lengths (symbols 257..285) and distances (0..29): base value and extra bits, RFC 1951 3.2.5.
-- Indexed by symbol - 256 and by distance symbol; symbols past the tables are invalid.
local LENGTH_BASE, LENGTH_EXTRA, DIST_BASE, DIST_EXTRA = {}, {}, {}, {}
do
  local base = 3
  for i = 1, 28 do
    local extra = i <= 8 and 0 or floor((i - 5) / 4)
    LENGTH_BASE[i], LENGTH_EXTRA[i] = base, extra
    base = base + POW2[extra]
  end
  LENGTH_BASE[29], LENGTH_EXTRA[29] = 258, 0
  base = 1
  for d = 0, 29 do
    local extra = d < 4 and 0 or floor(d / 2) - 1
    DIST_BASE[d], DIST_EXTRA[d] = base, extra
    base = base + POW2[extra]
  end
end

-- The order in which a dynamic block lists the code length code lengths (RFC 1951 3.2.7).
local CLEN_ORDER = { 16, 17, 18, 0, 8, 7, 9, 6, 10, 5, 11, 4, 12, 3, 13, 2, 14, 1, 15 }

-- Errors raised while decoding are tables with this metatable, so the public functions can
-- tell them from bugs and re-raise them at their caller's level.
local Failure = {}

--- Abort decoding with a message (formatted like string.format).
---@param fmt string
---@param ... any
local function fail(fmt, ...)
  error(setmetatable({ message = format(fmt, ...) }, Failure))
end

---@class png.Huffman
---@field symbol table<integer, integer> symbol for each value of the next `maxLength` bits
---@field length table<integer, integer> code length for each value (nil: no such code)
---@field maxLength integer longest code length (0 when the code is empty)
---@field size integer 2^maxLength

--- Build the lookup tables of a canonical Huffman code (RFC 1951 3.2.2) from its code lengths.
--- Incomplete codes are allowed (their unused bit patterns fail when met); over-subscribed
--- ones are not.
---@param lengths table<integer, integer> code length of each symbol, 0 = unused
---@param from integer index in `lengths` of symbol 0
---@param count integer number of symbols
---@param what string which code, for messages
---@return png.Huffman
local function buildHuffman(lengths, from, count, what)
  local perLength = {}
  for l = 0, 15 do perLength[l] = 0 end
  local maxLength = 0
  for s = 0, count - 1 do
    local l = lengths[from + s]
    if l > 0 then
      perLength[l] = perLength[l] + 1
      if l > maxLength then maxLength = l end
    end
  end
  local left = 1
  for l = 1, 15 do
    left = left * 2 - perLength[l]
    if left < 0 then fail('bad Huffman code: over-subscribed %s code lengths', what) end
  end
  local nextCode, code = {}, 0
  for l = 1, 15 do
    code = (code + perLength[l - 1]) * 2
    nextCode[l] = code
  end
  local size = POW2[maxLength]
  local symbol, length = {}, {}
  for s = 0, count - 1 do
    local l = lengths[from + s]
    if l > 0 then
      local c = nextCode[l]
      nextCode[l] = c + 1
      -- The code is sent most significant bit first: reverse it to index the LSB-first buffer.
      local reversed = 0
      for _ = 1, l do
        local bit = c % 2
        c = floor(c / 2)
        reversed = reversed * 2 + bit
      end
      for index = reversed, size - 1, POW2[l] do
        symbol[index], length[index] = s, l
      end
    end
  end
  return { symbol = symbol, length = length, maxLength = maxLength, size = size }
end

local fixedLiteral, fixedDistance

--- The codes of a fixed Huffman block (RFC 1951 3.2.6), built on first use.
---@return png.Huffman literal, png.Huffman distance
local function fixedCodes()
  if not fixedLiteral then
    local lengths = {}
    for s = 0, 287 do
      lengths[s] = (s <= 143 and 8) or (s <= 255 and 9) or (s <= 279 and 7) or 8
    end
    fixedLiteral = buildHuffman(lengths, 0, 288, 'fixed literal/length')
    for s = 0, 31 do lengths[s] = 5 end
    fixedDistance = buildHuffman(lengths, 0, 32, 'fixed distance')
  end
  return fixedLiteral, fixedDistance
end

--- Inflate a zlib stream (RFC 1950 around RFC 1951) into bytes.
---@param data integer[] the stream's bytes, 1-based
---@param n integer number of bytes in `data`
---@param expected integer exact number of bytes the stream must inflate to
---@return integer[] out the inflated bytes, 1-based
local function inflate(data, n, expected)
  if n < 2 then fail('truncated zlib data (%d bytes)', n) end
  local cmf, flg = data[1], data[2]
  if (cmf * 256 + flg) % 31 ~= 0 then fail('bad zlib header (check bits)') end
  if cmf % 16 ~= 8 then fail('bad zlib header (compression method %d, not 8 = deflate)', cmf % 16) end
  if cmf >= 128 then fail('bad zlib header (window size 2^%d)', floor(cmf / 16) + 8) end
  if flg % 64 >= 32 then fail('bad zlib header (preset dictionary not supported)') end

  local out, op = {}, 0
  local pos, bitBuffer, bitCount = 3, 0, 0

  --- Load whole bytes into the bit buffer while it holds at most 24 bits (so it stays below
  --- 2^32); fail if it still holds fewer than `k` bits at the end of the data.
  ---@param k integer
  local function need(k)
    while bitCount <= 24 do
      local b = data[pos]
      if not b then
        if bitCount < k then fail('truncated zlib data') end
        return
      end
      bitBuffer = bitBuffer + b * POW2[bitCount]
      pos = pos + 1
      bitCount = bitCount + 8
    end
  end

  --- Take the next `k` bits (k <= 16) as a number, first bit least significant.
  ---@param k integer
  ---@return integer
  local function bits(k)
    if bitCount < k then need(k) end
    local p = POW2[k]
    local v = bitBuffer % p
    bitBuffer = (bitBuffer - v) / p
    bitCount = bitCount - k
    return v
  end

  --- Decode one symbol of `code` (outside the hot loop).
  ---@param code png.Huffman
  ---@return integer
  local function decodeSymbol(code)
    if bitCount < code.maxLength then need(code.maxLength) end
    local index = bitBuffer % code.size
    local l = code.length[index]
    if not l then fail('bad Huffman code') end
    local p = POW2[l]
    bitBuffer = (bitBuffer - index % p) / p
    bitCount = bitCount - l
    return code.symbol[index]
  end

  --- Drop the bits up to the next byte boundary and give back the whole bytes still buffered.
  local function alignToByte()
    bits(bitCount % 8)
    while bitCount >= 8 do
      pos = pos - 1
      bitCount = bitCount - 8
    end
    bitBuffer = 0
  end

  --- Read the code lengths of a dynamic block and build its two codes (RFC 1951 3.2.7).
  ---@return png.Huffman literal, png.Huffman distance
  local function dynamicCodes()
    local nLiteral = bits(5) + 257
    local nDistance = bits(5) + 1
    local nCodeLength = bits(4) + 4
    if nLiteral > 286 then fail('bad dynamic block header (%d literal/length codes)', nLiteral) end
    if nDistance > 30 then fail('bad dynamic block header (%d distance codes)', nDistance) end
    local codeLengths = {}
    for i = 1, 19 do codeLengths[CLEN_ORDER[i]] = 0 end
    for i = 1, nCodeLength do codeLengths[CLEN_ORDER[i]] = bits(3) end
    local codeLengthCode = buildHuffman(codeLengths, 0, 19, 'code length')
    local lengths, i, total = {}, 0, nLiteral + nDistance
    while i < total do
      local sym = decodeSymbol(codeLengthCode)
      if sym < 16 then
        lengths[i] = sym
        i = i + 1
      else
        local value, repeats = 0 -- 16: the previous length 3-6 times; 17, 18: zeros
        if sym == 16 then
          if i == 0 then fail('bad code lengths (repeat with no previous length)') end
          value, repeats = lengths[i - 1], 3 + bits(2)
        else
          repeats = sym == 17 and 3 + bits(3) or 11 + bits(7)
        end
        if i + repeats > total then fail('bad code lengths (repeat past the last code)') end
        for j = i, i + repeats - 1 do lengths[j] = value end
        i = i + repeats
      end
    end
    if lengths[256] == 0 then fail('bad code lengths (no end-of-block code)') end
    return buildHuffman(lengths, 0, nLiteral, 'literal/length'),
      buildHuffman(lengths, nLiteral, nDistance, 'distance')
  end

  repeat
    local final = bits(1)
    local blockType = bits(2)
    if blockType == 0 then
      alignToByte()
      if pos + 3 > n then fail('truncated zlib data (stored block header)') end
      local len = data[pos] + data[pos + 1] * 256
      local nlen = data[pos + 2] + data[pos + 3] * 256
      if len + nlen ~= 65535 then fail('bad stored block length (LEN %d, NLEN %d)', len, nlen) end
      pos = pos + 4
      if pos + len - 1 > n then fail('truncated zlib data (stored block of %d bytes)', len) end
      if op + len > expected then
        fail('wrong decompressed size (more than the %d bytes expected)', expected)
      end
      for i = 0, len - 1 do out[op + 1 + i] = data[pos + i] end
      op = op + len
      pos = pos + len
    elseif blockType == 3 then
      fail('bad deflate block type 3')
    else
      local literal, distance
      if blockType == 1 then
        literal, distance = fixedCodes()
      else
        literal, distance = dynamicCodes()
      end
      local lSymbol, lLength, lMax, lSize = literal.symbol, literal.length, literal.maxLength, literal.size
      local dSymbol, dLength, dMax, dSize = distance.symbol, distance.length, distance.maxLength, distance.size
      -- The hot loop: the bit reading of need/bits/decodeSymbol written out in line.
      while true do
        if bitCount < lMax then need(lMax) end
        local index = bitBuffer % lSize
        local l = lLength[index]
        if not l then fail('bad Huffman code (literal/length)') end
        local p = POW2[l]
        bitBuffer = (bitBuffer - index % p) / p
        bitCount = bitCount - l
        local sym = lSymbol[index]
        if sym < 256 then
          if op >= expected then
            fail('wrong decompressed size (more than the %d bytes expected)', expected)
          end
          op = op + 1
          out[op] = sym
        elseif sym == 256 then
          break
        else
          sym = sym - 256
          local length = LENGTH_BASE[sym]
          if not length then fail('bad length code %d', sym + 256) end
          local e = LENGTH_EXTRA[sym]
          if e > 0 then
            if bitCount < e then need(e) end
            p = POW2[e]
            local v = bitBuffer % p
            bitBuffer = (bitBuffer - v) / p
            bitCount = bitCount - e
            length = length + v
          end
          if bitCount < dMax then need(dMax) end
          index = bitBuffer % dSize
          l = dLength[index]
          if not l then fail('bad Huffman code (distance)') end
          p = POW2[l]
          bitBuffer = (bitBuffer - index % p) / p
          bitCount = bitCount - l
          sym = dSymbol[index]
          local dist = DIST_BASE[sym]
          if not dist then fail('bad distance code %d', sym) end
          e = DIST_EXTRA[sym]
          if e > 0 then
            if bitCount < e then need(e) end
            p = POW2[e]
            local v = bitBuffer % p
            bitBuffer = (bitBuffer - v) / p
            bitCount = bitCount - e
            dist = dist + v
          end
          if dist > op then fail('bad distance %d (only %d bytes so far)', dist, op) end
          if op + length > expected then
            fail('wrong decompressed size (more than the %d bytes expected)', expected)
          end
          for i = op + 1, op + length do out[i] = out[i - dist] end
          op = op + length
        end
      end
    end
  until final == 1

  if op ~= expected then fail('wrong decompressed size (%d bytes, expected %d)', op, expected) end
  alignToByte()
  if pos + 3 > n then fail('truncated zlib data (no Adler-32)') end
  local a, b = 1, 0
  for start = 1, op, 4096 do
    local stop = start + 4095
    if stop > op then stop = op end
    for i = start, stop do
      a = a + out[i]
      b = b + a
    end
    a, b = a % 65521, b % 65521
  end
  local want = ((data[pos] * 256 + data[pos + 1]) * 256 + data[pos + 2]) * 256 + data[pos + 3]
  if b * 65536 + a ~= want then fail('bad zlib Adler-32 checksum') end
  return out
end

--- Undo the PNG row filters in place (PNG spec section 9). Each row is its filter-type byte
--- followed by `stride` bytes.
---@param raw integer[] the inflated bytes, 1-based
---@param stride integer bytes per row, without the filter-type byte
---@param height integer
---@param bpp integer bytes per complete pixel, at least 1 (the filters' left neighbour)
local function unfilter(raw, stride, height, bpp)
  local rowLength = stride + 1
  for y = 0, height - 1 do
    local first = y * rowLength + 2 -- index of the row's first byte (after its filter type)
    local last = first + stride - 1
    local filter = raw[first - 1]
    if filter == 1 then -- Sub
      for i = first + bpp, last do raw[i] = (raw[i] + raw[i - bpp]) % 256 end
    elseif filter == 2 then -- Up (nothing to add on the first row)
      if y > 0 then
        for i = first, last do raw[i] = (raw[i] + raw[i - rowLength]) % 256 end
      end
    elseif filter == 3 then -- Average
      if y > 0 then
        for i = first, first + bpp - 1 do raw[i] = (raw[i] + floor(raw[i - rowLength] / 2)) % 256 end
        for i = first + bpp, last do
          raw[i] = (raw[i] + floor((raw[i - bpp] + raw[i - rowLength]) / 2)) % 256
        end
      else
        for i = first + bpp, last do raw[i] = (raw[i] + floor(raw[i - bpp] / 2)) % 256 end
      end
    elseif filter == 4 then -- Paeth: on the first row it is Sub; its first pixel, Up
      if y > 0 then
        for i = first, first + bpp - 1 do raw[i] = (raw[i] + raw[i - rowLength]) % 256 end
        for i = first + bpp, last do
          local a, b, c = raw[i - bpp], raw[i - rowLength], raw[i - rowLength - bpp]
          local pa, pb, pc = b - c, a - c, a + b - c - c
          if pa < 0 then pa = -pa end
          if pb < 0 then pb = -pb end
          if pc < 0 then pc = -pc end
          if pa <= pb and pa <= pc then
            raw[i] = (raw[i] + a) % 256
          elseif pb <= pc then
            raw[i] = (raw[i] + b) % 256
          else
            raw[i] = (raw[i] + c) % 256
          end
        end
      else
        for i = first + bpp, last do raw[i] = (raw[i] + raw[i - bpp]) % 256 end
      end
    elseif filter ~= 0 then
      fail('bad filter type %d on row %d', filter, y)
    end
  end
end


---@class png.Image
---@field width integer
---@field height integer
---@field colourType integer 0 greyscale, 2 RGB, 3 palette, 4 greyscale + alpha, 6 RGBA
---@field bitDepth integer bits per sample: 1, 2, 4 or 8
---@field private bytes integer[] unfiltered rows, each after its filter-type byte
---@field private rowLength integer bytes per row, filter-type byte included
---@field private palette integer[]|nil r, g, b, a of palette entry i at 4i+1..4i+4
---@field private paletteSize integer|nil
---@field private key integer[]|nil tRNS colour key: the sample(s) of the transparent colour
local Image = {}
Image.__index = Image

--- The colour of one pixel.
---@param x integer 0-based column, 0 at the left
---@param y integer 0-based row, 0 at the top
---@return integer r, integer g, integer b, integer a each 0-255 (a is 255 without alpha)
function Image:pixel(x, y)
  if type(x) ~= 'number' or type(y) ~= 'number' or x % 1 ~= 0 or y % 1 ~= 0
    or x < 0 or y < 0 or x >= self.width or y >= self.height then
    error(format('png.Image:pixel: (%s, %s) is not a pixel of this %dx%d image',
      tostring(x), tostring(y), self.width, self.height), 2)
  end
  local bytes, colourType, depth = self.bytes, self.colourType, self.bitDepth
  local row = y * self.rowLength + 2 -- index of the row's first byte
  if colourType == 6 then
    local i = row + x * 4
    return bytes[i], bytes[i + 1], bytes[i + 2], bytes[i + 3]
  elseif colourType == 2 then
    local i = row + x * 3
    local r, g, b, key = bytes[i], bytes[i + 1], bytes[i + 2], self.key
    if key and r == key[1] and g == key[2] and b == key[3] then return r, g, b, 0 end
    return r, g, b, 255
  elseif colourType == 4 then
    local i = row + x * 2
    local v = bytes[i]
    return v, v, v, bytes[i + 1]
  end
  -- Greyscale or palette: one sample of `depth` bits, packed from the high bits of a byte.
  local v
  if depth == 8 then
    v = bytes[row + x]
  else
    local perByte = floor(8 / depth)
    local inByte = x % perByte
    v = floor(bytes[row + floor(x / perByte)] / POW2[8 - depth * (inByte + 1)]) % POW2[depth]
  end
  if colourType == 3 then
    if v >= self.paletteSize then
      error(format('png.Image:pixel: (%d, %d) has palette index %d, past the %d palette entries',
        x, y, v, self.paletteSize), 2)
    end
    local palette, i = self.palette, v * 4
    return palette[i + 1], palette[i + 2], palette[i + 3], palette[i + 4]
  end
  local key = self.key
  local a = (key and v == key[1]) and 0 or 255
  v = v * (255 / (POW2[depth] - 1)) -- scale 1, 2 and 4-bit greys to 0-255 (an exact integer)
  v = floor(v)
  return v, v, v, a
end

--- Big-endian unsigned number of `count` bytes at s[i..] (the caller checks the bounds).
---@param s string
---@param i integer
---@param count integer 2 or 4
---@return integer
local function bigEndian(s, i, count)
  local v = 0
  for k = i, i + count - 1 do v = v * 256 + byte(s, k) end
  return v
end

--- Copy a string's bytes into a number array.
---@param s string
---@return integer[] bytes, integer n
local function toBytes(s)
  local bytes, n = {}, #s
  for start = 1, n, 4096 do
    local chunk = { byte(s, start, start + 4095) }
    for i = 1, #chunk do bytes[start - 1 + i] = chunk[i] end
  end
  return bytes, n
end

--- Check and read an IHDR chunk's 13 bytes at s[i..] into a new image (no pixels yet).
---@param s string
---@param i integer
---@return png.Image
local function readHeader(s, i)
  local width, height = bigEndian(s, i, 4), bigEndian(s, i + 4, 4)
  local depth, colourType, compression, filtering, interlace = byte(s, i + 8, i + 12)
  if width == 0 or height == 0 or width >= 2 ^ 31 or height >= 2 ^ 31 then
    fail('bad image size %dx%d', width, height)
  end
  local depths = DEPTHS[colourType]
  if not depths then fail('bad colour type %d', colourType) end
  if not (' ' .. depths .. ' '):find(' ' .. depth .. ' ', 1, true) then
    fail('bad bit depth %d for colour type %d (%s allows %s)', depth, colourType, COLOUR_NAMES[colourType], depths)
  end
  if depth == 16 then fail('unsupported bit depth 16 (only 1, 2, 4 and 8)') end
  if compression ~= 0 then fail('unsupported compression method %d (only 0)', compression) end
  if filtering ~= 0 then fail('unsupported filter method %d (only 0)', filtering) end
  if interlace ~= 0 then fail('unsupported interlace method %d (only 0 = none)', interlace) end
  local rowBits = width * CHANNELS[colourType] * depth
  return setmetatable({
    width = width, height = height, colourType = colourType, bitDepth = depth,
    rowLength = floor((rowBits + 7) / 8) + 1,
  }, Image)
end

--- Read a tRNS chunk's `length` bytes at s[i..] into the image.
---@param image png.Image
---@param s string
---@param i integer
---@param length integer
local function readTransparency(image, s, i, length)
  local colourType = image.colourType
  if colourType == 3 then
    if not image.palette then fail('tRNS chunk before PLTE') end
    if length > image.paletteSize then
      fail('tRNS chunk of %d alpha values for %d palette entries', length, image.paletteSize)
    end
    for k = 0, length - 1 do image.palette[k * 4 + 4] = byte(s, i + k) end
  elseif colourType == 0 or colourType == 2 then
    local samples = colourType == 0 and 1 or 3
    if length ~= samples * 2 then fail('tRNS chunk of %d bytes for colour type %d', length, colourType) end
    local key = {}
    for k = 1, samples do key[k] = bigEndian(s, i + k * 2 - 2, 2) end
    image.key = key
  end -- (types 4 and 6 have an alpha channel: a tRNS chunk there is ignored)
end

--- Decode PNG bytes; raises Failure tables.
---@param s string
---@return png.Image
local function decode(s)
  if type(s) ~= 'string' then fail('expected the bytes of a PNG file as a string, got %s', type(s)) end
  local n = #s
  if sub(s, 1, 8) ~= SIGNATURE then
    fail(n < 8 and 'not a PNG file (%d bytes, shorter than the signature)' or 'not a PNG file (bad signature)', n)
  end
  local pos, image, idat = 9, nil, {}
  while true do
    if pos + 7 > n then fail('truncated data (file ends at byte %d, before the IEND chunk)', n) end
    local length, kind = bigEndian(s, pos, 4), sub(s, pos + 4, pos + 7)
    local first = pos + 8
    local last = first + length - 1
    if last + 4 > n then
      fail('truncated data (%s chunk of %d bytes at byte %d, file is %d bytes)', kind, length, pos, n)
    end
    if not image and kind ~= 'IHDR' then fail('first chunk is %q, not IHDR', kind) end
    if kind == 'IHDR' then
      if image then fail('second IHDR chunk') end
      if length ~= 13 then fail('IHDR chunk of %d bytes, not 13', length) end
      image = readHeader(s, first)
    elseif kind == 'PLTE' then
      if length % 3 ~= 0 or length == 0 or length > 768 then fail('PLTE chunk of %d bytes', length) end
      local palette = {}
      local size = floor(length / 3)
      for k = 0, size - 1 do
        local r, g, b = byte(s, first + k * 3, first + k * 3 + 2)
        palette[k * 4 + 1], palette[k * 4 + 2], palette[k * 4 + 3], palette[k * 4 + 4] = r, g, b, 255
      end
      image.palette, image.paletteSize = palette, size
    elseif kind == 'tRNS' then
      readTransparency(image, s, first, length)
    elseif kind == 'IDAT' then
      idat[#idat + 1] = sub(s, first, last)
    elseif kind == 'IEND' then
      break
    else
      local b = byte(kind, 1)
      if b >= 65 and b <= 90 then fail('unsupported critical chunk %q', kind) end
    end
    pos = last + 5
  end
  if #idat == 0 then fail('no IDAT chunk') end
  if image.colourType == 3 and not image.palette then fail('palette image without a PLTE chunk') end
  local data, count = toBytes(concat(idat))
  local stride = image.rowLength - 1
  local bytes = inflate(data, count, image.height * image.rowLength)
  local bitsPerPixel = CHANNELS[image.colourType] * image.bitDepth
  unfilter(bytes, stride, image.height, bitsPerPixel < 8 and 1 or floor(bitsPerPixel / 8))
  image.bytes = bytes
  return image
end

--- Re-raise an error from `decode` at the public function's caller (level 3 from here).
---@param err any
---@param prefix string
local function rethrow(err, prefix)
  if getmetatable(err) == Failure then error(prefix .. err.message, 3) end
  error(err, 0) -- a bug, not bad data: keep its own position
end

--- Decode the bytes of a PNG file (any colour type at bit depth 1-8, not interlaced).
---@param bytes string the whole file
---@return png.Image image `{ width = w, height = h }` with `image:pixel(x, y)` → r, g, b, a
function png.decode(bytes)
  local ok, image = pcall(decode, bytes)
  if not ok then rethrow(image, 'png.decode: ') end
  return image
end

--- Read a PNG file (opened in binary mode) and decode it like png.decode.
---@param path string
---@return png.Image image
function png.read(path)
  local file, err = io.open(path, 'rb')
  if not file then error(format('png.read: cannot open %s', tostring(err or path)), 2) end
  local s = file:read('*a')
  file:close()
  local ok, image = pcall(decode, s)
  if not ok then rethrow(image, format('png.read: %s: png.decode: ', path)) end
  return image
end

return png
