-- Property specs for rounded shapes (capsules, rounded rectangles, rounded hulls) against an
-- independent oracle written here: each shape is rebuilt from its constructor's arguments
-- as a core (a segment or a convex polygon, its hull by brute.hull) and a radius, and the
-- oracle measures distances to that core. Nothing of strike's geometry is read but the
-- answers under test. Reproduce a failure with STRIKE_SEED=<seed>.
local S = require 'strike'
local PRNG = require('spec.helpers.prng')
local brute = require('spec.property.brute')
local gen = require('spec.property.gen')

local H = S.hapes
local abs, sqrt, cos, sin, pi, max, min = math.abs, math.sqrt, math.cos, math.sin, math.pi, math.max, math.min

local SEED = PRNG.seedFromEnv(20261123)

local function g(v) return ('%.17g'):format(v) end

-- A random rounded shape and its oracle: { xs, ys, n (core), r, text }.
local function make(rng)
  local kind = rng:int(1, 3)
  local x, y, a = rng:range(-30, 30), rng:range(-30, 30), rng:range(-pi, pi)
  local c, s = cos(a), sin(a)
  if kind == 1 then
    local w = gen.logRange(rng, 0.2, 10)
    local h = w + (rng:next() < 0.1 and 0 or gen.logRange(rng, 0.1, 20))
    local half = (h - w) / 2 -- core from (0, -half) to (0, half), turned by a
    local o = { xs = { x + s * half, x - s * half }, ys = { y - c * half, y + c * half }, n = 2, r = w / 2,
      text = ('Capsule(%s, %s, %s, %s, %s)'):format(g(x), g(y), g(w), g(h), g(a)) }
    return H.Capsule(x, y, w, h, a), o
  elseif kind == 2 then
    local w, h = gen.logRange(rng, 0.5, 20), gen.logRange(rng, 0.5, 20)
    local r = rng:range(0.01, 0.49) * min(w, h)
    local xs, ys = {}, {}
    for i, p in ipairs({ { -1, -1 }, { 1, -1 }, { 1, 1 }, { -1, 1 } }) do
      local px, py = p[1] * (w / 2 - r), p[2] * (h / 2 - r)
      xs[i], ys[i] = x + c * px - s * py, y + s * px + c * py
    end
    local o = { xs = xs, ys = ys, n = 4, r = r,
      text = ('Rectangle(%s, %s, %s, %s, %s, %s)'):format(g(x), g(y), g(w), g(h), g(a), g(r)) }
    return H.Rectangle(x, y, w, h, a, r), o
  end
  while true do
    local k, size = rng:int(3, 9), gen.logRange(rng, 0.3, 10)
    local px, py = {}, {}
    for i = 1, k do px[i], py[i] = x + rng:range(-size, size), y + rng:range(-size, size) end
    local hx, hy, n = brute.hull(px, py, k)
    if n >= 3 and brute.shoelace(hx, hy, n) > 1e-3 * size * size then
      local r = gen.logRange(rng, 0.01, 5)
      local pts = { radius = r }
      for i = 1, n do pts[2 * i - 1], pts[2 * i] = hx[i], hy[i] end
      local list = {}
      for i = 1, 2 * n do list[i] = g(pts[i]) end
      local o = { xs = hx, ys = hy, n = n, r = r,
        text = ('ConvexPolygon({%s, radius = %s})'):format(table.concat(list, ', '), g(r)) }
      return H.ConvexPolygon(pts), o
    end
  end
end

-- The oracle: distance from (px, py) to the core (0 inside a polygon core).
local function coreDist(o, px, py)
  if o.n >= 3 and brute.shoelace(o.xs, o.ys, o.n) > 0 then
    local inside = true
    for i = 1, o.n do
      local j = i % o.n + 1
      if brute.cross(o.xs[i], o.ys[i], o.xs[j], o.ys[j], px, py) < 0 then inside = false end
    end
    if inside then return 0 end
  end
  local d = math.huge
  for i = 1, o.n do
    local j = i % o.n + 1
    d = min(d, brute.pointSegDist(px, py, o.xs[i], o.ys[i], o.xs[j], o.ys[j]))
  end
  return d
end

-- The point of the core's boundary nearest (px, py) (outside the core): qx, qy.
local function coreNearest(o, px, py)
  local best, bx, by = math.huge, 0, 0
  for i = 1, o.n do
    local j = i % o.n + 1
    local x1, y1, ex, ey = o.xs[i], o.ys[i], o.xs[j] - o.xs[i], o.ys[j] - o.ys[i]
    local e2 = ex * ex + ey * ey
    local t = e2 > 0 and max(0, min(1, ((px - x1) * ex + (py - y1) * ey) / e2)) or 0
    local qx, qy = x1 + t * ex, y1 + t * ey
    local d = (px - qx) ^ 2 + (py - qy) ^ 2
    if d < best then best, bx, by = d, qx, qy end
  end
  return bx, by
end

-- The oracle's interval of the line o + t u inside the shape: lo, hi, or nil. The distance
-- to a convex set is convex along a line, so its minimum is found by ternary search, and
-- the two crossings of the radius by bisection on each side.
local function lineSpan(o, ox, oy, ux, uy, reach)
  local function f(t) return coreDist(o, ox + t * ux, oy + t * uy) - o.r end
  local a, b = -reach, reach
  for _ = 1, 200 do
    local m1, m2 = a + (b - a) / 3, b - (b - a) / 3
    if f(m1) < f(m2) then b = m2 else a = m1 end
  end
  local tm = (a + b) / 2
  if f(tm) >= 0 then return nil end
  local lo, l1 = -reach, tm
  for _ = 1, 200 do
    local m = (lo + l1) / 2
    if f(m) < 0 then l1 = m else lo = m end
  end
  local h0, hi = tm, reach
  for _ = 1, 200 do
    local m = (h0 + hi) / 2
    if f(m) < 0 then h0 = m else hi = m end
  end
  return (lo + l1) / 2, (h0 + hi) / 2
end

describe('rounded shapes against an independent oracle', function()
  it('containsPoint is "nearer than the radius to the core"; project is the core\'s reach plus the radius',
    function()
      local rng = PRNG.new(SEED)
      local checked = 0
      for case = 1, 300 do
        local shape, o = make(rng)
        local where = ('seed %d case %d: %s'):format(SEED, case, o.text)
        local x0, y0, x1, y1 = shape:getBounds()
        for _ = 1, 40 do
          local px, py = rng:range(x0 - 1, x1 + 1), rng:range(y0 - 1, y1 + 1)
          local d = coreDist(o, px, py) - o.r
          if abs(d) > 1e-9 * (1 + o.r) then -- (not within round-off of the boundary)
            checked = checked + 1
            assert(shape:containsPoint(px, py) == (d < 0),
              ('%s: containsPoint(%s, %s) is %s, the oracle says %s'):format(where, g(px), g(py),
                tostring(shape:containsPoint(px, py)), g(d)))
          end
        end
        -- a hair inside and outside the boundary, along the way out from the nearest core point
        for _ = 1, 10 do
          local px, py = rng:range(x0 - 1, x1 + 1), rng:range(y0 - 1, y1 + 1)
          if coreDist(o, px, py) > 1e-6 * (1 + o.r) then
            local qx, qy = coreNearest(o, px, py)
            local dx, dy = px - qx, py - qy
            local l = sqrt(dx * dx + dy * dy)
            for _, f in ipairs({ 1 - 1e-7, 1 + 1e-7 }) do
              local tx, ty = qx + dx / l * o.r * f, qy + dy / l * o.r * f
              checked = checked + 1
              assert(shape:containsPoint(tx, ty) == (f < 1),
                ('%s: containsPoint(%s, %s), %s of the radius from the core, is %s'):format(where, g(tx), g(ty),
                  g(f), tostring(shape:containsPoint(tx, ty))))
            end
          end
        end
        local a = rng:range(-pi, pi)
        local nx, ny = cos(a), sin(a)
        local lo, hi = math.huge, -math.huge
        for i = 1, o.n do
          local p = o.xs[i] * nx + o.ys[i] * ny
          lo, hi = min(lo, p), max(hi, p)
        end
        local plo, phi = shape:project(nx, ny)
        local tol = 1e-9 * (1 + abs(lo) + abs(hi) + o.r)
        assert(abs(plo - (lo - o.r)) <= tol and abs(phi - (hi + o.r)) <= tol,
          ('%s: project(%s, %s) = %s, %s; oracle %s, %s'):format(where, g(nx), g(ny), g(plo), g(phi),
            g(lo - o.r), g(hi + o.r)))
        -- the bounds are the projections on the axes
        local bx0, bx1 = shape:project(1, 0)
        local by0, by1 = shape:project(0, 1)
        assert(abs(bx0 - x0) <= tol and abs(bx1 - x1) <= tol and abs(by0 - y0) <= tol and abs(by1 - y1) <= tol,
          where .. ': the bounds are not the projections on the axes')
      end
      assert.is_true(checked > 8000)
    end)

  it('rayCast and rayIntersections give the oracle\'s interval of the ray inside the shape', function()
    local rng = PRNG.new(SEED + 1)
    local hits = 0
    for case = 1, 400 do
      local shape, o = make(rng)
      local cx, cy = shape:getCentroid()
      local R = shape:getRadius()
      local a = rng:range(-pi, pi)
      local d = rng:range(0, 1.3) * R -- (from the line's distance to the centroid: hits and misses)
      local dir = rng:range(-pi, pi)
      local ux, uy = cos(dir), sin(dir)
      -- an origin 3 radii back along the ray, offset sideways by d (or, one time in four, inside)
      local ox, oy = cx - 3 * R * ux - d * uy * cos(a), cy - 3 * R * uy + d * ux * cos(a)
      if case % 4 == 0 then ox, oy = cx + rng:range(-0.3, 0.3) * R, cy + rng:range(-0.3, 0.3) * R end
      local where = ('seed %d case %d: %s, ray from (%s, %s) along (%s, %s)'):format(SEED + 1, case, o.text,
        g(ox), g(oy), g(ux), g(uy))
      local lo, hi = lineSpan(o, ox, oy, ux, uy, 10 * R + 10 * (abs(ox - cx) + abs(oy - cy)))
      local t, hx, hy, nx, ny = shape:rayCast(ox, oy, ux, uy)
      local tol = 1e-7 * (1 + R)
      if lo and hi >= 0 and hi - lo > tol then
        hits = hits + 1
        local want = lo >= 0 and lo or hi
        assert(t and abs(t - want) <= tol, ('%s: rayCast %s, oracle %s'):format(where, tostring(t), g(want)))
        assert(abs(hx - (ox + t * ux)) <= tol and abs(hy - (oy + t * uy)) <= tol, where .. ': hit point off the ray')
        assert(abs(nx * nx + ny * ny - 1) <= 1e-12, where .. ': normal not unit')
        -- the normal is the outward normal of the boundary there: a step along it leaves the
        -- shape, a step against it enters (the oracle's distance grows along it)
        local e = 1e-4 * (1 + o.r)
        local dOut = coreDist(o, hx + nx * e, hy + ny * e) - o.r
        local dIn = coreDist(o, hx - nx * e, hy - ny * e) - o.r
        assert(dOut > 0 and dIn < dOut, ('%s: normal (%s, %s) is not outward'):format(where, g(nx), g(ny)))
        local ts, n = shape:rayIntersections(ox, oy, ux, uy)
        if lo >= 0 then
          assert(n == 2 and abs(ts[1] - lo) <= tol and abs(ts[2] - hi) <= tol,
            ('%s: rayIntersections %s, oracle %s %s'):format(where, ts and table.concat(ts, ', ') or 'nil', g(lo),
              g(hi)))
        else
          assert(n == 1 and abs(ts[1] - hi) <= tol, where .. ': rayIntersections from inside')
        end
      elseif not lo or hi < -tol then
        assert(t == nil, ('%s: rayCast hit at %s, the oracle misses'):format(where, tostring(t)))
      end
    end
    assert.is_true(hits > 150)
  end)

  it('contact points lie midway between the surfaces: within half the depth of both shapes', function()
    local rng = PRNG.new(SEED + 2)
    local colliding = 0
    for case = 1, 400 do
      local a, oa = make(rng)
      local b, ob = make(rng)
      local ax, ay = a:getCentroid()
      local bx, by = b:getCentroid()
      local k = rng:range(0, 1) * (a:getRadius() + b:getRadius()) / (sqrt((bx - ax) ^ 2 + (by - ay) ^ 2) + 1e-9)
      b:translate((ax - bx) + (bx - ax) * k, (ay - by) + (by - ay) * k) -- (b's centroid toward a's)
      -- b's oracle moved with it
      local mx, my = b:getCentroid()
      local sx, sy = mx - bx, my - by
      for i = 1, ob.n do ob.xs[i], ob.ys[i] = ob.xs[i] + sx, ob.ys[i] + sy end
      local m = S.AT(a, b)
      if not m.separating then
        colliding = colliding + 1
        local c = S.ite(m)
        local where = ('seed %d case %d: %s / %s (moved by %s, %s)'):format(SEED + 2, case, oa.text, ob.text, g(sx),
          g(sy))
        assert(c and c.count >= 1 and c.count <= 2, where .. ': no contact points')
        local tol = 1e-7 * (1 + a:getRadius() + b:getRadius())
        for i = 1, c.count do
          local p = c[i]
          assert(p.depth > 0 and p.depth <= m.depth * (1 + 1e-9) + tol,
            ('%s: point %d depth %s, the MTV\'s %s'):format(where, i, g(p.depth), g(m.depth)))
          for _, o in ipairs({ oa, ob }) do
            local d = coreDist(o, p.x, p.y) - o.r
            assert(d <= p.depth / 2 + tol, ('%s: point %d (%s, %s) is %s outside %s, more than half its depth %s')
              :format(where, i, g(p.x), g(p.y), g(d), o.text, g(p.depth)))
          end
        end
      end
    end
    assert.is_true(colliding > 150)
  end)
end)
