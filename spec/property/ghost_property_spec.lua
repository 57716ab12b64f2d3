-- Property specs for chains (S.trikers.Chain): random chains, random shapes, checked
-- against an independent reading of the rules in strike/collide/chain.lua.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local gen = require('spec.property.gen')
local sat = require('strike.collide.sat')

local SEED = PRNG.seedFromEnv(2020)
local T = S.trikers
local abs, sqrt, cos, sin, pi, huge, min = math.abs, math.sqrt, math.cos, math.sin, math.pi, math.huge, math.min
local SLACK = 1e-9 -- on sines; the library uses 1e-12

-- A random chain: an open polyline with turns of 0.05 to 2.5 radians either way, or a
-- star-shaped loop in either winding. Returns the Chain and whether it is a loop.
local function randomChain(rng)
  local ox, oy = rng:range(-50, 50), rng:range(-50, 50)
  local pts = {}
  if rng:next() < 0.5 then
    local k, heading, x, y = rng:int(2, 8), rng:range(-pi, pi), ox, oy
    pts[1], pts[2] = x, y
    for i = 1, k do
      local len = gen.logRange(rng, 1, 8)
      x, y = x + len * cos(heading), y + len * sin(heading)
      pts[2 * i + 1], pts[2 * i + 2] = x, y
      heading = heading + (rng:next() < 0.5 and -1 or 1) * rng:range(0.05, 2.5)
    end
    return T.Chain(pts), false
  end
  while true do
    local k, base, angles = rng:int(3, 9), rng:range(-pi, pi), {}
    for i = 1, k do angles[i] = base + 2 * pi * (i - 1 + rng:range(0.1, 0.9)) / k end
    local reverse = rng:next() < 0.5
    for i = 1, k do
      local a, r = angles[reverse and k + 1 - i or i], gen.logRange(rng, 2, 10)
      pts[2 * i - 1], pts[2 * i] = ox + r * cos(a), oy + r * sin(a)
    end
    -- keep corners clearly convex or concave (nothing within 1e-6 of straight)
    local ok = true
    for i = 1, k do
      local h, j = (i - 2) % k + 1, i % k + 1
      local ax, ay = pts[2 * i - 1] - pts[2 * h - 1], pts[2 * i] - pts[2 * h]
      local bx, by = pts[2 * j - 1] - pts[2 * i - 1], pts[2 * j] - pts[2 * i]
      if abs(ax * by - ay * bx) < 1e-6 * sqrt((ax * ax + ay * ay) * (bx * bx + by * by)) then ok = false end
    end
    if ok then return T.Chain(pts, true), true end
  end
end

-- The segment's frame from its public geometry: p1, unit tangent e, normal n = (ey, -ex).
local function frame(seg)
  local x1, y1, x2, y2 = seg:getEdge(1)
  local ex, ey = x2 - x1, y2 - y1
  local l = sqrt(ex * ex + ey * ey)
  ex, ey = ex / l, ey / l
  return x1, y1, x2, y2, ex, ey, ey, -ex, l
end

-- The rule, read independently: is the unit normal (mx, my), from the segment toward the
-- other shape, admissible? (m == n, or inside the cone of a convex corner; an open end is
-- convex, with the outward tangent as the far side of its cone.)
local function admissible(seg, mx, my)
  local x1, y1, x2, y2, ex, ey, nx, ny = frame(seg)
  local x0, y0, x3, y3 = seg:getGhostVertices()
  local c = nx * my - ny * mx
  if abs(c) <= SLACK and nx * mx + ny * my > 0 then return true end
  if c < 0 then
    local gx, gy, convex = -ex, -ey, true
    if x0 then
      local dx, dy = x1 - x0, y1 - y0
      local d = sqrt(dx * dx + dy * dy)
      dx, dy = dx / d, dy / d
      gx, gy, convex = dy, -dx, dx * ey - dy * ex > 0
    end
    return convex and gx * my - gy * mx >= -SLACK
  end
  local gx, gy, convex = ex, ey, true
  if x3 then
    local dx, dy = x3 - x2, y3 - y2
    local d = sqrt(dx * dx + dy * dy)
    dx, dy = dx / d, dy / d
    gx, gy, convex = dy, -dx, ex * dy - ey * dx > 0
  end
  return convex and mx * gy - my * gx >= -SLACK
end

-- How far `shape` reaches behind the segment's line.
local function backReach(seg, shape)
  local x1, y1, _, _, _, _, nx, ny = frame(seg)
  if shape:getVertexCount() == 0 then
    local cx, cy = shape:getCentroid()
    return shape:getRadius() - (nx * (cx - x1) + ny * (cy - y1))
  end
  local lo = huge
  for i = 1, shape:getVertexCount() do
    local x, y = shape:getVertex(i)
    lo = min(lo, nx * (x - x1) + ny * (y - y1))
  end
  return -lo
end

local function isBehind(seg, shape)
  local x1, y1, _, _, _, _, nx, ny = frame(seg)
  local cx, cy = shape:getCentroid()
  return nx * (cx - x1) + ny * (cy - y1) < 0
end

-- The plain two-sided edge test, the segment being an ordinary two-vertex polygon.
local function plain(a, b)
  local out = S.MTV()
  if a:getKind() == 'circle' then return sat.polygonCircle(b, a, out, true) end
  if b:getKind() == 'circle' then return sat.polygonCircle(a, b, out) end
  return sat.polygonPolygon(a, b, out)
end

-- A random shape of any kind (polygons, circles, edges) centred at (x, y).
local function randomShape(rng, x, y)
  return gen.shape(S, rng, gen.pick(rng, 'any'), x, y)
end

local function show(seg, shape)
  local x1, y1, x2, y2 = seg:getEdge(1)
  local x0, y0, x3, y3 = seg:getGhostVertices()
  return ('segment (%.17g, %.17g)-(%.17g, %.17g), ghosts %s %s %s %s; shape %s'):format(x1, y1, x2, y2,
    tostring(x0), tostring(y0), tostring(x3), tostring(y3), gen.show(shape))
end

-- A shape placed near the segment: `along` in [0, 1] from p1 to p2 (may exceed), `off`
-- from its line along n.
local function placeNear(rng, seg, along, off)
  local x1, y1, _, _, ex, ey, nx, ny, l = frame(seg)
  local shape = randomShape(rng, 0, 0)
  shape:translateTo(x1 + ex * along * l + nx * off, y1 + ey * along * l + ny * off)
  return shape
end

local function segmentsOf(c)
  local list = {}
  for s in c:elems() do list[#list + 1] = s end
  return list
end

describe('chain properties', function()
  it('far from the ends, the chain result is the plain edge result, or its push along n', function()
    local rng = PRNG.new(SEED)
    local same, snapped = 0, 0
    for case = 1, 500 do
      -- a long middle segment between random neighbours
      local a = rng:range(-pi, pi)
      local L = rng:range(60, 120)
      local x1, y1 = rng:range(-50, 50), rng:range(-50, 50)
      local x2, y2 = x1 + L * cos(a), y1 + L * sin(a)
      local t0, t1 = a + pi + rng:range(-2.5, 2.5), a + rng:range(-2.5, 2.5)
      local c = T.Chain(x1 + 5 * cos(t0), y1 + 5 * sin(t0), x1, y1, x2, y2, x2 + 5 * cos(t1), y2 + 5 * sin(t1))
      local seg = segmentsOf(c)[2]
      local _, _, _, _, ex, ey, nx, ny = frame(seg)
      local shape
      if case > 400 then
        -- a triangle across the line, its flat side in front (by top) parallel to the
        -- segment, its apex behind (by 1.1 to 1.9 top): the centroid is in front, but the
        -- plain edge test pushes it through, along -n, the shallower way
        local top, w, along = rng:range(0.5, 3), rng:range(0.5, 4), rng:range(10, L - 10)
        local apex = top * rng:range(1.1, 1.9)
        local px, py = x1 + ex * along, y1 + ey * along
        shape = S.hapes.ConvexPolygon(px - ex * w + nx * top, py - ey * w + ny * top, px + ex * w + nx * top,
          py + ey * w + ny * top, px - nx * apex, py - ny * apex)
      else
        shape = placeNear(rng, seg, 0, 0)
        local r = shape:getRadius()
        local along = rng:range(r + 1, L - r - 1)
        local off = rng:range(-0.2, 1.1) * r
        shape:translateTo(x1 + ex * along + nx * off, y1 + ey * along + ny * off)
      end
      local what = ('seed %d case %d: %s'):format(SEED, case, show(seg, shape))
      for _, flip in ipairs({ false, true }) do
        local A, B = seg, shape
        if flip then A, B = shape, seg end
        local p, m = plain(A, B), S.AT(A, B)
        local sign = flip and -1 or 1
        if p.separating then
          assert(m.separating and m.depth == p.depth and m.nx == p.nx and m.ny == p.ny, what .. ': a miss changed')
        elseif isBehind(seg, shape) then
          assert(m.separating, what .. ': collided from behind')
        elseif admissible(seg, sign * p.nx, sign * p.ny) then
          assert(m.x == p.x and m.y == p.y and m.nx == p.nx and m.ny == p.ny and m.depth == p.depth
            and m.edgeIndex == p.edgeIndex and m.separating == p.separating, what .. ': not the plain result')
          same = same + 1
        else
          local d = backReach(seg, shape)
          assert(abs(m.nx - sign * nx) < 1e-12 and abs(m.ny - sign * ny) < 1e-12, what .. ': not pushed along n')
          assert(abs(m.depth - d) <= 1e-9 * (1 + d), ('%s: depth %.17g, back reach %.17g'):format(what, m.depth, d))
          assert(m.edgeIndex == sign and m.separating == (d <= 0), what .. ': wrong edge index or flag')
          snapped = snapped + 1
        end
      end
    end
    assert(same > 300, ('seed %d: only %d plain results'):format(SEED, same))
    assert(snapped >= 180, ('seed %d: only %d replaced results'):format(SEED, snapped))
  end)

  it('never collides with a shape whose centroid is behind the segment', function()
    local rng = PRNG.new(SEED + 1)
    local behind = 0
    for case = 1, 300 do
      local c = randomChain(rng)
      local segs = segmentsOf(c)
      local seg = segs[rng:int(1, #segs)]
      local shape = placeNear(rng, seg, rng:range(-0.3, 1.3), -rng:range(0, 4))
      if isBehind(seg, shape) then
        behind = behind + 1
        local what = ('seed %d case %d: %s'):format(SEED, case, show(seg, shape))
        local m1, m2 = S.AT(seg, shape), S.AT(shape, seg)
        assert(m1.separating and m1.depth <= 0, what .. ': collided (segment first)')
        assert(m2.separating and m2.depth <= 0, what .. ': collided (segment second)')
      end
    end
    assert(behind > 250, ('seed %d: only %d shapes behind'):format(SEED, behind))
  end)

  it('pushes only along admissible normals, and only where the plain edge test collides', function()
    local rng = PRNG.new(SEED + 2)
    local hits, corners = 0, 0
    for case = 1, 300 do
      local c = randomChain(rng)
      local segs = segmentsOf(c)
      local seg = segs[rng:int(1, #segs)]
      -- near a corner half of the time, anywhere along the segment otherwise
      local along = rng:next() < 0.5 and (rng:next() < 0.5 and 0 or 1) + rng:range(-0.1, 0.1) or rng:range(0, 1)
      local shape = placeNear(rng, seg, along, rng:range(-0.5, 1.2) * 3)
      local body = T.Collider(shape)
      for _, s in ipairs(segs) do
        local what = ('seed %d case %d: %s'):format(SEED, case, show(s, shape))
        for _, flip in ipairs({ false, true }) do
          local m = flip and S.AT(shape, s) or S.AT(s, shape)
          if not m.separating then
            hits = hits + 1
            local sign = flip and -1 or 1
            assert(m.depth > 0, what .. ': a collision without depth')
            assert(admissible(s, sign * m.nx, sign * m.ny),
              ('%s: normal (%.17g, %.17g) not admissible%s'):format(what, m.nx, m.ny, flip and ' (flipped)' or ''))
            assert(not isBehind(s, shape), what .. ': collided from behind')
            local p = flip and plain(shape, s) or plain(s, shape)
            assert(not p.separating, what .. ': the plain edge test says they do not even touch')
            if p.nx ~= m.nx or p.ny ~= m.ny then
              corners = corners + 1
              assert(m.edgeIndex == sign, what .. ': replaced, but the edge index is not the segment\'s face 1')
              local d = backReach(s, shape)
              assert(abs(m.depth - d) <= 1e-9 * (1 + d), ('%s: depth %.17g, back reach %.17g'):format(what, m.depth, d))
            end
          end
        end
      end
      -- and S.triking keeps one of those
      local m = S.triking(c, body)
      if m then
        assert(admissible(m.colliderShape, m.nx, m.ny), ('seed %d case %d: S.triking normal not admissible'):format(
          SEED, case))
        local contacts = S.ite(m)
        assert(contacts and contacts.count >= 1, ('seed %d case %d: no contact points'):format(SEED, case))
      end
    end
    assert(hits > 200, ('seed %d: only %d collisions'):format(SEED, hits))
    assert(corners > 10, ('seed %d: only %d replaced normals'):format(SEED, corners))
  end)
end)
