--- Random shape generators for the property specs, driven by spec/helpers/prng.lua so
--- that every VM builds the same shapes from the same seed.
local brute = require('spec.property.brute')

local gen = {}

local pi, cos, sin, sqrt = math.pi, math.cos, math.sin, math.sqrt

-- Log-uniform in [a, b]: thin and fat shapes alike.
local function logRange(rng, a, b)
  return a * (b / a) ^ rng:next()
end
gen.logRange = logRange

-- The hull of the k points in pts = {x1, y1, ...} as a flat vertex list (ConvexPolygon
-- rejects interior points, so strike is handed only the hull), or nil when it is flat.
local function hullOf(pts, k)
  local xs, ys = {}, {}
  for i = 1, k do xs[i], ys[i] = pts[2 * i - 1], pts[2 * i] end
  local hx, hy, h = brute.hull(xs, ys, k)
  if h < 3 then return nil end
  local flat = {}
  for i = 1, h do flat[2 * i - 1], flat[2 * i] = hx[i], hy[i] end
  return flat
end

--- A random convex shape of the given kind centred near (cx, cy).
--- Kinds: 'rect', 'ngon', 'hull', 'ellipse', 'circle', 'edge'.
function gen.shape(S, rng, kind, cx, cy)
  local angle = rng:range(-pi, pi)
  if kind == 'rect' then
    return S.hapes.Rectangle(cx, cy, logRange(rng, 0.1, 8), logRange(rng, 0.1, 8), angle)
  elseif kind == 'ngon' then
    return S.hapes.RegularPolygon(cx, cy, rng:int(3, 16), logRange(rng, 0.3, 5), angle)
  elseif kind == 'ellipse' then
    return S.hapes.Ellipse(cx, cy, logRange(rng, 0.3, 5), logRange(rng, 0.3, 5), rng:int(3, 20), angle)
  elseif kind == 'hull' then
    local size = logRange(rng, 0.3, 5)
    while true do
      local pts, k = {}, rng:int(3, 12)
      for i = 1, k do
        local a, r = rng:range(0, 2 * pi), size * sqrt(rng:next())
        pts[2 * i - 1], pts[2 * i] = cx + r * cos(a), cy + r * sin(a)
      end
      -- random points are rarely convex in position: hand strike their hull
      local flat = hullOf(pts, k)
      if flat then
        local ok, shape = pcall(S.hapes.ConvexPolygon, flat)
        if ok then return shape end
      end
    end
  elseif kind == 'circle' then
    return S.hapes.Circle(cx, cy, logRange(rng, 0.2, 5))
  elseif kind == 'edge' then
    local h = logRange(rng, 0.2, 5)
    local dx, dy = h * cos(angle), h * sin(angle)
    return S.hapes.Edge(cx - dx, cy - dy, cx + dx, cy + dy)
  end
  error('unknown kind ' .. tostring(kind))
end

--- A random shape on a small integer grid, to provoke exact alignments: shared edge
--- lines, vertices on edges, circle centres on an edge's line.
function gen.gridShape(S, rng, kind, cx, cy)
  cx, cy = math.floor(cx), math.floor(cy)
  if kind == 'circle' then
    return S.hapes.Circle(cx + rng:int(-2, 2), cy + rng:int(-2, 2), rng:int(1, 3))
  elseif kind == 'edge' then
    local x1, y1 = cx + rng:int(-3, 3), cy + rng:int(-3, 3)
    local x2, y2 = x1, y1
    local mode = rng:int(1, 3) -- horizontal, vertical, diagonal
    while x2 == x1 and y2 == y1 do
      if mode == 1 then x2 = cx + rng:int(-3, 3)
      elseif mode == 2 then y2 = cy + rng:int(-3, 3)
      else local d = rng:int(-3, 3); x2, y2 = x1 + d, y1 + d end
    end
    return S.hapes.Edge(x1, y1, x2, y2)
  elseif kind == 'hull' then
    while true do
      local pts, k = {}, rng:int(3, 6)
      for i = 1, k do pts[2 * i - 1], pts[2 * i] = cx + rng:int(-3, 3), cy + rng:int(-3, 3) end
      local flat = hullOf(pts, k)
      if flat then return S.hapes.ConvexPolygon(flat) end
    end
  end
  -- anything else: an axis-aligned rectangle with integer corners
  return S.hapes.Rectangle(cx + rng:int(-2, 2), cy + rng:int(-2, 2), 2 * rng:int(1, 3), 2 * rng:int(1, 3))
end

gen.polygonKinds = { 'rect', 'ngon', 'hull', 'ellipse' }
gen.allKinds = { 'rect', 'ngon', 'hull', 'ellipse', 'circle', 'edge' }

--- Resolve a kind class: 'poly' picks a random polygon kind, 'any' any kind.
function gen.pick(rng, kind)
  if kind == 'poly' then return gen.polygonKinds[rng:int(1, #gen.polygonKinds)] end
  if kind == 'any' then return gen.allKinds[rng:int(1, #gen.allKinds)] end
  return kind
end

--- A random pair (a, b) of the given kinds ('poly', 'any' or a kind). b's centre sits
--- at a random offset from a's, of length uniform in [0, 1.2 * (radius a + radius b)].
--- When `want` is true (false), pairs are drawn until the oracle says they overlap (do
--- not), so alternating `want` gives half overlapping pairs for every pair type. With
--- `grid`, both shapes come from the integer grid instead. Returns a, b.
function gen.pair(S, rng, kindA, kindB, want, grid)
  while true do
    local a, b
    local ka, kb = gen.pick(rng, kindA), gen.pick(rng, kindB)
    local ox, oy = rng:range(-50, 50), rng:range(-50, 50)
    if grid then
      a = gen.gridShape(S, rng, ka, ox, oy)
      b = gen.gridShape(S, rng, kb, ox + rng:int(-3, 3), oy + rng:int(-3, 3))
    else
      a = gen.shape(S, rng, ka, ox, oy)
      b = gen.shape(S, rng, kb, ox, oy)
      local d = rng:range(0, 1.2) * (a:getRadius() + b:getRadius())
      local t = rng:range(0, 2 * pi)
      b:translate(d * cos(t), d * sin(t))
    end
    if want == nil or brute.overlaps(brute.of(a), brute.of(b)) == want then return a, b end
  end
end

--- A short description of a shape for failure messages: its class and its vertices
--- (or centre and radius), at full precision.
function gen.show(s)
  if s:getVertexCount() == 0 then
    local x, y = s:getCentroid()
    return ('Circle(%.17g, %.17g, %.17g)'):format(x, y, s:getRadius())
  end
  local v = s:getVertices()
  local parts = {}
  for i = 1, #v do parts[i] = ('%.17g'):format(v[i]) end
  local cls = s:getVertexCount() == 2 and 'Edge' or 'ConvexPolygon'
  return cls .. '(' .. table.concat(parts, ', ') .. ')'
end

--- n sorted random angles in [0, 2 pi) whose every gap, the wrap-around one included, lies
--- in (1e-3, 0.9 pi): the vertices of a star-shaped outline at these angles (any radii) make
--- each edge a chord of its own sector, so the outline is simple (a gap of pi or more would
--- let an edge cross others). Draws again until the gaps fit.
function gen.starAngles(rng, n)
  local angles
  repeat
    angles = {}
    for i = 1, n do angles[i] = rng:range(0, 2 * pi) end
    table.sort(angles)
    local gap = 2 * pi - angles[n] + angles[1]
    local ok = gap > 1e-3 and gap < 0.9 * pi
    for i = 2, n do
      gap = angles[i] - angles[i - 1]
      ok = ok and gap > 1e-3 and gap < 0.9 * pi
    end
  until ok
  return angles
end

return gen
