--- A concave (simple) polygon, split into few convex pieces.
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(ROOT .. '.colliders.Collider')
local ConvexPolygon = require(ROOT .. '.shapes.ConvexPolygon')
local seamOf = require(ROOT .. '.base.VertexShape')._seamOf
local decompose = require(ROOT .. '.geometry.decompose')
local check = require(ROOT .. '.check')
local badSelf, type = check.badSelf, type

local abs, sqrt = math.abs, math.sqrt

---@class strike.Concave : strike.Collider
local Concave = Collider:extend()
Concave.name = 'Concave'

-- Seams ---------------------------------------------------------------------------------
--
-- The cuts the decomposition adds are not surfaces: each piece's faces get seam flags
-- (`_seams`, documented in strike/base/VertexShape.lua) that the collider queries read. The
-- pieces are made of the input's own coordinates, so faces are compared exactly, by vertex:
--   * a face whose reverse is a face of another piece is a cut: a seam;
--   * a face between consecutive vertices of the cleaned outline is an outline edge;
--   * any other face lies along collinear outline edges and cuts (the bar of a T, whose top
--     face runs under the stem: outline, cut, outline), or along a cut whose other side is
--     covered by a longer face. Its seam parts are where the reversed faces of other pieces
--     of this kind overlap it (the rest of it faces the outside). A cut meets the outline at
--     vertices only, so these faces are few, and only they are compared with each other.
-- A face of a piece is collinear with another within COLLINEAR of its length (the
-- decomposition calls a corner straight below a turn of 1e-12).
local COLLINEAR = 1e-10

-- The id of each distinct point: ids[x][y], the first input index at it (-0.0 is 0.0).
local function pointIds(xs, ys, n)
  local ids = {}
  for i = 1, n do
    local x, y = xs[i], ys[i]
    if x == 0 then x = 0 end
    if y == 0 then y = 0 end
    local col = ids[x]
    if not col then
      col = {}
      ids[x] = col
    end
    if not col[y] then col[y] = i end
  end
  return ids
end

local function idOf(ids, x, y)
  if x == 0 then x = 0 end
  if y == 0 then y = 0 end
  local col = ids[x]
  return col and col[y]
end

-- The seam of the face r of `faces` (flat x1, y1, x2, y2 per face) from the reversed faces
-- among its candidates `near` (face numbers) that lie on it: true, a list of parts, or false.
local function overlaps(faces, r, near)
  local q = 4 * r - 3
  local px, py = faces[q], faces[q + 1]
  local ex, ey = faces[q + 2] - px, faces[q + 3] - py
  local len2 = ex * ex + ey * ey
  local len = sqrt(len2)
  local tol = COLLINEAR * len
  local parts, np = nil, 0
  for c = 1, #near do
    local o = 4 * near[c] - 3
    local rx, ry, sx, sy = faces[o] - px, faces[o + 1] - py, faces[o + 2] - px, faces[o + 3] - py
    if (sx - rx) * ex + (sy - ry) * ey < 0 and abs(ex * ry - ey * rx) <= tol * len
      and abs(ex * sy - ey * sx) <= tol * len then
      local a, b = (sx * ex + sy * ey) / len2, (rx * ex + ry * ey) / len2 -- (reversed: s first)
      if a < 0 then a = 0 end
      if b > 1 then b = 1 end
      if (b - a) * len > tol then
        parts = parts or {}
        parts[np + 1], parts[np + 2] = a, b
        np = np + 2
      end
    end
  end
  return seamOf(parts, np, len, tol)
end

-- Candidates for overlaps: near[r] lists the faces (of the m in `faces`) whose extents along
-- an axis overlap face r's. A sweep along the axis (0.8, 0.6), which no edge of a grid
-- outline is perpendicular to: collinear faces that overlap have overlapping extents, and
-- faces apart along the axis are never compared (a comb's bar is compared with every tooth,
-- each tooth with the bar only).
local function candidates(faces, m)
  local lo, hi, order, near = {}, {}, {}, {}
  for r = 1, m do
    local q = 4 * r - 3
    local a, b = 0.8 * faces[q] + 0.6 * faces[q + 1], 0.8 * faces[q + 2] + 0.6 * faces[q + 3]
    if a > b then a, b = b, a end
    local pad = COLLINEAR * (b - a + abs(a) + abs(b)) -- (generous: the test is exact later)
    lo[r], hi[r], order[r], near[r] = a - pad, b + pad, r, {}
  end
  table.sort(order, function(u, v)
    if lo[u] ~= lo[v] then return lo[u] < lo[v] end
    return u < v
  end)
  for i = 1, m do
    local f = order[i]
    local top, nf = hi[f], near[f]
    for j = i + 1, m do
      local g = order[j]
      if lo[g] > top then break end
      local ng = near[g]
      nf[#nf + 1], ng[#ng + 1] = g, f
    end
  end
  return near
end

-- The seam of every face of every piece (pieces as decompose gives them, made of the
-- points xs, ys, 1..n): seams[p][j] for face j of piece p (vertex j to j + 1), true, a list
-- of parts or false; and whether any face is a seam.
local function pieceSeams(pieces, xs, ys, n)
  local ids = pointIds(xs, ys, n)
  local vid, used, face = {}, {}, {}
  for p = 1, #pieces do
    local piece, v = pieces[p], {}
    for j = 1, #piece / 2 do
      local id = idOf(ids, piece[2 * j - 1], piece[2 * j])
      v[j] = id or false
      if id then used[id] = true end
    end
    vid[p] = v
    for j = 1, #v do
      local a, b = v[j], v[j % #v + 1]
      if a and b then face[a * (n + 1) + b] = true end
    end
  end
  -- the cleaned outline: the points the pieces use, in input order, repeats dropped
  -- (a point met again is a repeat: decompose refuses outlines that touch themselves)
  local pos, m = {}, 0
  for i = 1, n do
    local id = idOf(ids, xs[i], ys[i])
    if used[id] and not pos[id] then
      m = m + 1
      pos[id] = m
    end
  end
  local function outlineEdge(a, b)
    local pa, pb = pos[a], pos[b]
    if not (pa and pb) then return false end
    local d = abs(pa - pb)
    return d == 1 or d == m - 1
  end

  local seams, any = {}, false
  local rest, restFace, nrest = {}, {}, 0 -- faces neither cut nor outline edge: x1, y1, x2, y2
  for p = 1, #pieces do
    local piece, v, s = pieces[p], vid[p], {}
    local k = #v
    for j = 1, k do
      local a, b = v[j], v[j % k + 1]
      if a and b and face[b * (n + 1) + a] then
        s[j], any = true, true
      else
        s[j] = false
        if a and b and not outlineEdge(a, b) then
          local jn = j % k + 1
          rest[4 * nrest + 1], rest[4 * nrest + 2] = piece[2 * j - 1], piece[2 * j]
          rest[4 * nrest + 3], rest[4 * nrest + 4] = piece[2 * jn - 1], piece[2 * jn]
          nrest = nrest + 1
          restFace[2 * nrest - 1], restFace[2 * nrest] = p, j
        end
      end
    end
    seams[p] = s
  end
  local near = candidates(rest, nrest)
  for r = 1, nrest do
    local seam = overlaps(rest, r, near[r])
    if seam then
      seams[restFace[2 * r - 1]][restFace[2 * r]], any = seam, true
    end
  end
  return seams, any
end

--- A collider for the simple polygon x1, y1, x2, y2, ... (or one table {x1, y1, ...}), in
--- either winding. It holds convex pieces that tile the outline exactly (triangulation by
--- monotone partition, then Hertel-Mehlhorn merging; O(n log n) for n vertices).
--- The cuts between pieces are seams, not surfaces: containsPoint is true on them, and the
--- rays of the collider queries cross them without a hit (each piece's `_seams`, see
--- strike/base/VertexShape.lua).
--- Self-intersecting or degenerate outlines are an error.
---@param ... number|number[]
function Concave:new(...)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Concave:new') end
  local xs, ys, n = check.coordinates('strike.Concave', ...)
  local pieces, err = decompose.decompose(xs, ys, n)
  if not pieces then check.fail('strike.Concave: ' .. err) end
  local seams, anySeam = nil, false
  if #pieces > 1 then seams, anySeam = pieceSeams(pieces, xs, ys, n) end
  local built = {}
  for i = 1, #pieces do
    -- (built as ConvexPolygon(pieces[i]) would be, but an error, such as a piece outside
    -- strike's limits on lengths, names strike.Concave)
    local piece = setmetatable({ _fname = 'strike.Concave' }, ConvexPolygon)
    piece:new(pieces[i])
    piece._fname = nil
    if anySeam then
      -- (mapped onto the built polygon's faces by geometry: its hull may start elsewhere or
      -- drop a corner that turns by less than 1e-10)
      local src, count, coords, s = {}, 0, pieces[i], seams[i]
      local k = #s
      for j = 1, k do
        if s[j] then
          local jn = j % k + 1
          src[5 * count + 1], src[5 * count + 2] = coords[2 * j - 1], coords[2 * j]
          src[5 * count + 3], src[5 * count + 4], src[5 * count + 5] = coords[2 * jn - 1], coords[2 * jn], s[j]
          count = count + 1
        end
      end
      if count > 0 then piece._seams = piece:_seamsFrom(src, count) end
    end
    built[i] = piece
  end
  Collider._take(self, built) -- (Collider.new(self, ...) without the checks: the pieces are new)
end

return Concave
