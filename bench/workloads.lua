--- Seeded benchmark workloads, identical on every VM. A workload is a list of pairs of
--- plain shape descriptions (no library objects), so every adapter builds the same scene:
---   { kind = 'rect', x =, y =, w =, h =, angle = }
---   { kind = 'ngon', x =, y =, n =, r =, angle = }       regular n-gon, circumradius r
---   { kind = 'circle', x =, y =, r = }
---   { kind = 'edge', x1 =, y1 =, x2 =, y2 = }
--- and compound bodies { kind = 'compound', parts = { desc, ... } }.
--- Each pair is classified with the independent oracle of the property specs
--- (spec/property/brute.lua), so that every workload holds exactly the requested share of
--- overlapping pairs, and every pair's bounding boxes overlap (except in 'aabb': boxes
--- whose bounds overlap always hit, so its misses have their bounds apart).
---
--- Pairs come from rejection sampling: candidates are drawn until one has the verdict
--- wanted next (alternately a hit and a miss), overlapping bounds and no near-touching part
--- pair. Most candidates are turned down, so before building shapes and asking the oracle,
--- a candidate is checked against discs around each part (every point of a part lies within
--- its circumradius of its centre; every point within its inradius is inside): when these
--- already prove the verdict is the unwanted one, or that the bounding boxes are apart, it is
--- dropped at once. That check only turns down candidates the oracle would turn down too, so
--- the workload is exactly the one the oracle alone would give; every pair kept is still
--- classified by the oracle.
local S = require('strike')
local PRNG = require('spec.helpers.prng')
local brute = require('spec.property.brute')

local pi = math.pi
local W = {}

local function rect(rng, x, y)
  return { kind = 'rect', x = x, y = y, w = rng:range(10, 60), h = rng:range(10, 60), angle = rng:range(0, pi) }
end

local function ngon(n)
  return function(rng, x, y)
    -- circumradius from a side length of 10 to 60 px: side = 2 r sin(pi / n)
    return { kind = 'ngon', x = x, y = y, n = n, r = rng:range(10, 60) / (2 * math.sin(pi / n)),
      angle = rng:range(0, 2 * pi) }
  end
end

local function circle(rng, x, y)
  return { kind = 'circle', x = x, y = y, r = rng:range(5, 30) }
end

local function edge(rng, x, y)
  local a, l = rng:range(0, 2 * pi), rng:range(10, 60)
  local dx, dy = math.cos(a) * l / 2, math.sin(a) * l / 2
  return { kind = 'edge', x1 = x - dx, y1 = y - dy, x2 = x + dx, y2 = y + dy }
end

local function aabb(rng, x, y)
  return { kind = 'rect', x = x, y = y, w = rng:range(10, 60), h = rng:range(10, 60), angle = 0 }
end

local function rectOrOctagon(rng, x, y)
  if rng:next() < 0.5 then return rect(rng, x, y) end
  return ngon(8)(rng, x, y)
end

--- Build a strike shape from a description.
---@param d table
---@return table shape
function W.strikeShape(d)
  local H = S.hapes
  if d.kind == 'rect' then return H.Rectangle(d.x, d.y, d.w, d.h, d.angle) end
  if d.kind == 'ngon' then return H.RegularPolygon(d.x, d.y, d.n, d.r, d.angle) end
  if d.kind == 'circle' then return H.Circle(d.x, d.y, d.r) end
  if d.kind == 'edge' then return H.Edge(d.x1, d.y1, d.x2, d.y2) end
  error('no such shape kind ' .. tostring(d.kind))
end

--- The vertices of a 'rect' or 'ngon' description as a flat list {x1, y1, ...}: about its
--- own centre and unrotated, or, when `placed`, turned by its angle and moved to its centre
--- (for the peers' adapters, which build polygons from vertices).
---@param d table @param placed boolean|nil
---@return number[]
function W.vertices(d, placed)
  local v
  if d.kind == 'rect' then
    local hx, hy = d.w / 2, d.h / 2
    v = { -hx, -hy, hx, -hy, hx, hy, -hx, hy }
  else
    v = {}
    for i = 1, d.n do
      local a = -2 * math.pi * i / d.n
      v[#v + 1], v[#v + 2] = d.r * math.sin(a), d.r * math.cos(a)
    end
  end
  if placed then
    local c, s = math.cos(d.angle), math.sin(d.angle)
    for j = 1, #v, 2 do
      v[j], v[j + 1] = d.x + c * v[j] - s * v[j + 1], d.y + s * v[j] + c * v[j + 1]
    end
  end
  return v
end

local function bounds(list)
  local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
  for i = 1, #list do
    local a, b, c, d = list[i]:getBounds()
    x0, y0, x1, y1 = math.min(x0, a), math.min(y0, b), math.max(x1, c), math.max(y1, d)
  end
  return x0, y0, x1, y1
end

-- Does some part of body a overlap some part of body b (per the oracle)? Also returns
-- the smallest |signed distance| over part pairs (to keep away from touching), and, for a
-- single pair of shapes, the penetration depth when they overlap.
local function classify(pa, pb)
  local hit, margin, sd = false, math.huge, nil
  for i = 1, #pa do
    for j = 1, #pb do
      local da, db = brute.of(pa[i]), brute.of(pb[j])
      sd = brute.signedDistance(da, db)
      if sd < 0 then hit = true end
      margin = math.min(margin, math.abs(sd))
    end
  end
  return hit, margin, (hit and #pa == 1 and #pb == 1) and -sd or nil
end

local function parts(d)
  if d.kind == 'compound' then
    local list = {}
    for i, p in ipairs(d.parts) do list[i] = W.strikeShape(p) end
    return list
  end
  return { W.strikeShape(d) }
end

-- Discs of a body's parts, from the descriptions alone, appended to the flat list `out`
-- after its first 4 * n entries: centre x, y, circumradius (the part lies in that disc) and
-- inradius (the open disc of that radius lies inside the part; 0 for a segment, whose
-- midpoint is its centre). Returns the new count.
local function discs(d, out, n)
  local k = d.kind
  local x, y, R, r
  if k == 'compound' then
    for _, p in ipairs(d.parts) do n = discs(p, out, n) end
    return n
  elseif k == 'circle' then
    x, y, R, r = d.x, d.y, d.r, d.r
  elseif k == 'rect' then
    x, y, R, r = d.x, d.y, math.sqrt(d.w * d.w + d.h * d.h) / 2, math.min(d.w, d.h) / 2
  elseif k == 'ngon' then
    x, y, R, r = d.x, d.y, d.r, d.r * math.cos(pi / d.n)
  elseif k == 'edge' then
    local dx, dy = d.x2 - d.x1, d.y2 - d.y1
    x, y, R, r = (d.x1 + d.x2) / 2, (d.y1 + d.y2) / 2, math.sqrt(dx * dx + dy * dy) / 2, 0
  else
    error('no such shape kind ' .. tostring(k))
  end
  local i = 4 * n
  out[i + 1], out[i + 2], out[i + 3], out[i + 4] = x, y, R, r
  return n + 1
end

-- Far above the rounding of shapes built from these descriptions (coordinates < 1000).
local SLACK = 1e-6

-- The box around n discs of a flat list.
local function discBox(c, n)
  local x0, y0, x1, y1 = math.huge, math.huge, -math.huge, -math.huge
  for i = 0, 4 * (n - 1), 4 do
    local x, y, R = c[i + 1], c[i + 2], c[i + 3]
    if x - R < x0 then x0 = x - R end
    if y - R < y0 then y0 = y - R end
    if x + R > x1 then x1 = x + R end
    if y + R > y1 then y1 = y + R end
  end
  return x0, y0, x1, y1
end

-- Can the discs alone tell that the oracle would turn this candidate down? True when the
-- bodies' boxes are certainly apart (unless `anyBounds`), or when the verdict is certainly
-- not `want`: some part pair's inner discs overlap (a hit), or every part pair's outer
-- discs are apart (a miss).
local function surelyRejected(ca, na, cb, nb, want, anyBounds)
  if not anyBounds then
    local ax0, ay0, ax1, ay1 = discBox(ca, na)
    local bx0, by0, bx1, by1 = discBox(cb, nb)
    if ax1 + SLACK < bx0 or bx1 + SLACK < ax0 or ay1 + SLACK < by0 or by1 + SLACK < ay0 then return true end
  end
  local allApart = true
  for i = 0, 4 * (na - 1), 4 do
    for j = 0, 4 * (nb - 1), 4 do
      local dx, dy = cb[j + 1] - ca[i + 1], cb[j + 2] - ca[i + 2]
      local dist = math.sqrt(dx * dx + dy * dy)
      if dist < ca[i + 4] + cb[j + 4] - SLACK then return not want end
      if dist <= ca[i + 3] + cb[j + 3] + SLACK then allApart = false end
    end
  end
  return allApart and want
end

-- `count` pairs from makeA / makeB, half overlapping, all with overlapping bounds unless
-- `anyBounds` (axis-aligned boxes miss exactly when their bounds are apart).
local function pairsOf(seed, count, makeA, makeB, anyBounds)
  local rng = PRNG.new(seed)
  local list, want = {}, true
  local ca, cb = {}, {}
  while #list < count do
    local a = makeA(rng, 0, 0)
    local b = makeB(rng, rng:range(-70, 70), rng:range(-70, 70))
    if not surelyRejected(ca, discs(a, ca, 0), cb, discs(b, cb, 0), want, anyBounds) then
      local pa, pb = parts(a), parts(b)
      local ax0, ay0, ax1, ay1 = bounds(pa)
      local bx0, by0, bx1, by1 = bounds(pb)
      if anyBounds or (ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1) then
        local hit, margin, depth = classify(pa, pb)
        if hit == want and margin > 1e-6 then
          list[#list + 1] = { a, b, hit = hit, depth = depth }
          want = not want
        end
      end
    end
  end
  return list
end

local function compound(rng, x, y)
  return { kind = 'compound', parts = {
    rect(rng, x - 20, y), circle(rng, x + 20, y), ngon(8)(rng, x, y - 25),
  } }
end

--- The pair workloads, in report order: name, description, generator.
W.pairWorkloads = {
  { name = 'poly-poly', what = 'rotated rectangles and 8-gons', a = rectOrOctagon, b = rectOrOctagon },
  { name = 'circle-poly', what = 'circle against rectangle or 8-gon', a = circle, b = rectOrOctagon },
  { name = 'circle-circle', what = 'circles', a = circle, b = circle },
  { name = 'edge-poly', what = 'segment against rectangle or 8-gon', a = edge, b = rectOrOctagon },
  { name = '4-gons', what = 'regular 4-gons', a = ngon(4), b = ngon(4) },
  { name = '8-gons', what = 'regular 8-gons', a = ngon(8), b = ngon(8) },
  { name = '16-gons', what = 'regular 16-gons', a = ngon(16), b = ngon(16) },
  { name = 'compound', what = 'colliders of rectangle + circle + 8-gon', a = compound, b = compound },
  { name = 'aabb', what = 'axis-aligned rectangles (misses: bounds apart)', a = aabb, b = aabb, anyBounds = true },
}

--- Generate the pairs of a named workload.
---@param name string @param count integer @param seed integer
---@return table[] pairs, each { descA, descB, hit = boolean, depth = oracle's penetration depth
---   (hits between two single shapes only) }
function W.generate(name, count, seed)
  for i, w in ipairs(W.pairWorkloads) do
    if w.name == name then return pairsOf(seed + i, count, w.a, w.b, w.anyBounds) end
  end
  error('no workload ' .. name)
end

--- Where to put a workload's pairs in one world (bench/lovephysics's narrow section, where
--- Box2D finds them with its broadphase): pair k on cell k of a square grid centred on the
--- origin, its first body at the cell's centre. `apart` false: the second body where the
--- workload has it relative to the first (the pair's overlap as it is); true: the second body
--- half a cell to the right of the first, clear of it. The cell's side is the least for which
--- the bodies of different pairs, and in `apart` the two of a pair, stay `gap` apart or more,
--- each body taken as the disc around its centre that holds it (circumradius): 2 (D + R) +
--- gap, and 2 (2 R + gap) for `apart`, whichever is larger (both layouts use the same), where
--- R is the largest circumradius and D the largest distance between a pair's two centres.
--- Single shapes only ('rect', 'ngon', 'circle', 'edge').
---@param list table[] pairs { descA, descB }
---@param apart boolean
---@param gap number
---@return number[] ax x of each pair's first body
---@return number[] ay
---@return number[] bx x of each pair's second body
---@return number[] by
---@return number side the cell's side
function W.layout(list, apart, gap)
  local n, R, D = #list, 0, 0
  local ca, cb = {}, {}
  for k = 1, n do
    local a, b = list[k][1], list[k][2]
    if a.kind == 'compound' or b.kind == 'compound' then error('W.layout: single shapes only', 2) end
    discs(a, ca, 0)
    discs(b, cb, 0)
    local dx, dy = cb[1] - ca[1], cb[2] - ca[2]
    R = math.max(R, ca[3], cb[3])
    D = math.max(D, math.sqrt(dx * dx + dy * dy))
  end
  local side = math.max(2 * (D + R) + gap, 2 * (2 * R + gap))
  local cols = math.ceil(math.sqrt(n))
  local rows = math.ceil(n / cols)
  local ax, ay, bx, by = {}, {}, {}, {}
  for k = 1, n do
    local gx = ((k - 1) % cols - (cols - 1) / 2) * side
    local gy = (math.floor((k - 1) / cols) - (rows - 1) / 2) * side
    discs(list[k][1], ca, 0)
    discs(list[k][2], cb, 0)
    ax[k], ay[k] = gx, gy
    if apart then
      bx[k], by[k] = gx + side / 2, gy
    else
      bx[k], by[k] = gx + (cb[1] - ca[1]), gy + (cb[2] - ca[2])
    end
  end
  return ax, ay, bx, by, side
end

--- Outlines for the Concave construction table, as flat lists {x1, y1, ...} of n vertices:
---   'star'  a random star: one vertex in each of n equal angular sectors (so at sorted random
---           angles), each at a random radius in [0.2, 1] -- spiky, about half the vertices
---           reflex;
---   'regular'  a regular star of n / 2 spikes (n even): tips at radius 1, notches at 0.5 --
---           the worst case for the pieces: a piece of n / 2 vertices in the middle, every face
---           of it a cut (issue 21);
---   'comb'  a comb of n / 4 rectangular teeth on a base (n a multiple of 4).
---@param kind string @param n integer @param seed integer
---@return number[]
function W.outline(kind, n, seed)
  local v = {}
  if kind == 'star' then
    local rng = PRNG.new(seed)
    for i = 1, n do
      local a, r = 2 * pi * (i - 1 + rng:range(0.05, 0.95)) / n, rng:range(0.2, 1)
      v[2 * i - 1], v[2 * i] = r * math.cos(a), r * math.sin(a)
    end
  elseif kind == 'regular' then
    for i = 1, n do
      local a, r = pi * (i - 1) / (n / 2), i % 2 == 1 and 1 or 0.5
      v[2 * i - 1], v[2 * i] = r * math.cos(a), r * math.sin(a)
    end
  elseif kind == 'comb' then
    local teeth = n / 4
    v = { 0, 0, 2 * teeth - 1, 0 }
    for k = teeth - 1, 0, -1 do
      local x = 2 * k
      v[#v + 1], v[#v + 2], v[#v + 3], v[#v + 4] = x + 1, 3, x, 3
      if k > 0 then v[#v + 1], v[#v + 2], v[#v + 3], v[#v + 4] = x, 1, x - 1, 1 end
    end
  else
    error('no outline kind ' .. tostring(kind))
  end
  return v
end

--- Frame workload for transforms: `count` bodies to move, turn and bound every frame.
---@param count integer @param seed integer
---@return table[] descriptions
function W.bodies(count, seed)
  local rng = PRNG.new(seed)
  local list = {}
  for i = 1, count do list[i] = rectOrOctagon(rng, rng:range(0, 800), rng:range(0, 600)) end
  return list
end

--- A Tiled map in the table shape of Tiled's Lua export, for S.tiled's load time: a
--- size x size tile layer of 16 px tiles (collidable) in which each cell holds a solid tile
--- with probability `density`, two tiles of the tileset alternating (the regions mix them),
--- and an object layer (collidable) of `objects` objects spread over the map: a fifth each
--- rectangles (a third of them rotated), ellipses (half of them round), convex and concave
--- polygons, and polylines and points (a tenth each), with random sizes of 8-40 px.
---@param size integer @param density number @param objects integer @param seed integer
---@return table map
function W.tiledMap(size, density, objects, seed)
  local rng = PRNG.new(seed)
  local data = {}
  for i = 1, size * size do
    data[i] = rng:next() < density and (i % 2 + 1) or 0
  end
  local span = size * 16
  local objs = {}
  for i = 1, objects do
    local x, y, w, h = rng:range(0, span), rng:range(0, span), rng:range(8, 40), rng:range(8, 40)
    local kind = (i - 1) % 10
    local o = { id = i, name = '', type = '', x = x, y = y, width = 0, height = 0, rotation = 0, visible = true,
      properties = {} }
    if kind <= 1 then
      o.shape, o.width, o.height = 'rectangle', w, h
      if kind == 1 and i % 3 == 0 then o.rotation = rng:range(0, 360) end
    elseif kind <= 3 then
      o.shape, o.width, o.height = 'ellipse', w, kind == 2 and w or h
    elseif kind <= 5 then
      o.shape = 'polygon'
      local n = rng:int(3, 8)
      local pts = {}
      for k = 1, n do
        local a = 2 * pi * (k - 1) / n
        local r = kind == 4 and w or (k % 2 == 0 and w or w / 2)
        pts[k] = { x = r * math.cos(a), y = r * math.sin(a) }
      end
      o.polygon = pts
    elseif kind <= 7 then
      o.shape = 'polyline'
      o.polyline = { { x = 0, y = 0 }, { x = w, y = 0 }, { x = w + h, y = h / 2 } }
    else
      o.shape = 'point'
    end
    objs[i] = o
  end
  return {
    version = '1.10', luaversion = '5.1', orientation = 'orthogonal', renderorder = 'right-down',
    width = size, height = size, tilewidth = 16, tileheight = 16, nextlayerid = 3, nextobjectid = objects + 1,
    properties = {},
    tilesets = { { name = 'ground', firstgid = 1, tilewidth = 16, tileheight = 16, spacing = 0, margin = 0,
      columns = 2, tileoffset = { x = 0, y = 0 }, properties = {}, tilecount = 2, tiles = {} } },
    layers = {
      { type = 'tilelayer', x = 0, y = 0, width = size, height = size, id = 1, name = 'ground', visible = true,
        opacity = 1, offsetx = 0, offsety = 0, properties = { collidable = true }, encoding = 'lua', data = data },
      { type = 'objectgroup', draworder = 'topdown', id = 2, name = 'objects', visible = true, opacity = 1,
        offsetx = 0, offsety = 0, properties = { collidable = true }, objects = objs },
    },
  }
end

return W
