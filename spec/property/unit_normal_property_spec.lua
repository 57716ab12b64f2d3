-- Property-based specs: every normal strike reports is a unit vector (|n|^2 within 1e-12
-- of 1), for shapes of every size strike accepts (strike/limits.lua: lengths from 1e-100
-- to 1e100) and for distances between shapes of any size; what a constructor refuses a
-- transform refuses too. Reproduce a failure with STRIKE_SEED=<seed> (any VM); the message
-- names the seed, the case and the shapes at full precision.
local S = require 'strike'
local layout = require 'strike.base.layout'
local PRNG = require('spec.helpers.prng')
local brute = require('spec.property.brute')
local rb = require('spec.property.ray_brute')
local gen = require('spec.property.gen')

local abs, max, min, sqrt, cos, sin, pi, huge = math.abs, math.max, math.min, math.sqrt, math.cos, math.sin, math.pi,
  math.huge
local H, T = S.hapes, S.trikers

local SEED = PRNG.seedFromEnv(20250214)

local function g(v) return ('%.17g'):format(v) end

-- 10^u, u uniform in [a, b]
local function pow10(rng, a, b) return 10 ^ rng:range(a, b) end

local function isUnit(nx, ny)
  return type(nx) == 'number' and type(ny) == 'number' and abs(nx * nx + ny * ny - 1) <= 1e-12
end

-- A random shape of any kind (gen's kinds and points) near the origin, then scaled about
-- the origin by `k` (strike refuses a scale that would take it out of its limits: then
-- nil and the error).
local KINDS = { 'rect', 'ngon', 'hull', 'ellipse', 'circle', 'edge', 'point', 'chain', 'capsule', 'concave' }
local BODIES = { chain = true, capsule = true, concave = true } -- (colliders)
local function makeShape(rng, kind, k)
  local s
  local x, y, w, h = rng:range(-50, 50), rng:range(-50, 50), gen.logRange(rng, 0.2, 5), gen.logRange(rng, 0.2, 5)
  if kind == 'point' then
    s = H.Point(x, y)
  elseif kind == 'chain' then
    s = T.Chain(x, y, x + w, y, x + w, y + h, x + 2 * w, y + h * rng:range(-1, 1), rng:next() < 0.5)
  elseif kind == 'capsule' then
    s = T.Capsule(x, y, w, w + h, rng:range(-pi, pi))
  elseif kind == 'concave' then
    s = T.Concave(x, y, x + 2 * w, y, x + 2 * w, y + h, x + w, y + h, x + w, y + 2 * h, x, y + 2 * h)
  else
    s = gen.shape(S, rng, kind, rng:range(-50, 50), rng:range(-50, 50))
  end
  local ok, err = pcall(s.scale, s, k, 0, 0)
  if not ok then return nil, err end
  return s
end

-- A ray for a shape (description D) in a random mode: ox, oy, dx, dy, the mode, and for
-- rays aimed at an inner point that must hit, the point's x.
local MODES = { 'random', 'interior', 'inside', 'vertex', 'along', 'graze', 'far', 'farAxis', 'length' }
local function makeRay(rng, D)
  local cx, cy, R = rb.boundingCircle(D)
  if R == 0 then R = max(abs(cx), abs(cy), 1) * 1e-3 end -- (a point)
  local mode = MODES[rng:int(1, #MODES)]
  local a = rng:range(-pi, pi)
  local ux, uy = cos(a), sin(a)
  if mode == 'interior' or mode == 'inside' or mode == 'far' or mode == 'farAxis' then
    local qx, qy = cx, cy
    if not D.circle or D.r > 0 then qx, qy = rb.interiorPoint(D, rng) end
    if mode == 'farAxis' then
      local d = rng:int(1, 4)
      ux, uy = ({ 1, -1, 0, 0 })[d], ({ 0, 0, 1, -1 })[d]
    end
    local dist = 0
    if mode == 'interior' then dist = R * rng:range(1.1, 4) end
    if mode == 'far' or mode == 'farAxis' then dist = min(R * pow10(rng, 6, 300), 1e300) end
    local len = pow10(rng, -3, 3)
    -- (a far ray that is not axis-aligned is exact only for a direction a rounding away from
    -- the one given: it must hit only while that rounding, 1e-16 of the distance, is small)
    local aim = not (mode == 'far' and dist > 1e10 * R)
    return qx - dist * ux, qy - dist * uy, ux * len, uy * len, mode, aim and qx, qy
  elseif mode == 'vertex' and not D.circle then
    local i = rng:int(1, D.n)
    return D.xs[i] - 2 * R * ux, D.ys[i] - 2 * R * uy, ux, uy, mode
  elseif mode == 'along' and not D.circle then -- along an edge's line, from before it
    local i = rng:int(1, D.n)
    local j = i < D.n and i + 1 or 1
    local ex, ey = D.xs[j] - D.xs[i], D.ys[j] - D.ys[i]
    local back = rng:range(0, 2)
    return D.xs[i] - back * ex, D.ys[i] - back * ey, ex, ey, mode
  elseif mode == 'graze' and D.circle and D.r > 0 then -- tangent to the circle
    return D.x + D.r * uy - 3 * D.r * ux, D.y - D.r * ux - 3 * D.r * uy, ux, uy, mode
  elseif mode == 'length' then -- direction vectors of extreme lengths
    local k = rng:next() < 0.5 and pow10(rng, -300, -200) or pow10(rng, 200, 300)
    return cx - 3 * R * ux, cy - 3 * R * uy, k * ux, k * uy, mode
  end
  local d = R * rng:range(0, 3)
  return cx + d * cos(a + 1), cy + d * sin(a + 1), ux, uy, 'random'
end

describe('unit normals', function()
  it('every ray hit of rayCast and segmentCast, on shapes, chains, capsules, concave colliders, from anywhere',
    function()
      local rng = PRNG.new(SEED)
      local CASES, hits, refused = 1500, 0, 0
      for case = 1, CASES do
        local kind = KINDS[(case - 1) % #KINDS + 1]
        local k = pow10(rng, -95, 95)
        if case % 3 == 0 then k = 1 end
        local s = makeShape(rng, kind, k)
        if not s then
          refused = refused + 1
        else
          local body = BODIES[kind]
          -- (a body: rays at one of its leaves)
          local D = brute.of(body and select(rng:int(1, select('#', s:unpack())), s:unpack()) or s)
          local ox, oy, dx, dy, mode, aimed = makeRay(rng, D)
          local c = T.Collider(s:copy())
          local function check(cond, what, t, hx, hy, nx, ny)
            if not cond then
              error(('seed %d case %d (%s, scaled by %s, %s ray from %s, %s along %s, %s): %s gave %s, (%s, %s),'
                .. ' normal (%s, %s); %s'):format(SEED, case, kind, g(k), mode, g(ox), g(oy), g(dx), g(dy), what,
                tostring(t), tostring(hx), tostring(hy), tostring(nx), tostring(ny),
                body and 'a body' or gen.show(s)), 2)
            end
          end
          local function unitHit(what, t, hx, hy, nx, ny)
            if t == nil then return end
            hits = hits + 1
            check(t >= 0 and t < huge and isUnit(nx, ny), what, t, hx, hy, nx, ny)
          end
          unitHit('rayCast', s:rayCast(ox, oy, dx, dy))
          unitHit('collider rayCast', c:rayCast(ox, oy, dx, dy))
          local l = rng:range(0, 4)
          local ex, ey = ox + l * dx, oy + l * dy
          if ex - ex == 0 and ey - ey == 0 then
            unitHit('segmentCast', s:segmentCast(ox, oy, ex, ey))
            unitHit('collider segmentCast', c:segmentCast(ox, oy, ex, ey))
          end
          if not body then
            local ts, n = s:rayIntersections(ox, oy, dx, dy)
            for i = 1, n do
              check(ts[i] >= 0 and ts[i] < huge and (i == 1 or ts[i] >= ts[1]), 'rayIntersections', ts[i])
            end
          end
          local aimedMode = mode == 'far' or mode == 'farAxis' or mode == 'interior'
          if not body and aimedMode and aimed and not (D.circle and D.r == 0) then
            -- aimed at an inner point: a hit, whose normal faces the ray (it enters)
            local t, hx, hy, nx, ny = s:rayCast(ox, oy, dx, dy)
            check(t ~= nil, 'a miss, aimed at an inner point:', t)
            local len = sqrt(dx * dx + dy * dy)
            if D.n ~= 2 and not rb.inside(D, ox, oy) then
              check(nx * dx / len + ny * dy / len <= 1e-9, 'an entering normal', t, hx, hy, nx, ny)
            end
            if mode == 'farAxis' then -- exact from any distance: as from nearby
              local R = select(3, rb.boundingCircle(D))
              check(rb.boundaryDist(D, hx, hy) <= 1e-9 * (R + abs(hx) + abs(hy)), 'a hit on the boundary', t, hx, hy,
                nx, ny)
            end
          end
        end
      end
      assert.is_true(hits > CASES, ('only %d hits'):format(hits))
      assert.is_true(refused < CASES / 10, ('%d shapes refused'):format(refused))
    end)

  it('S.AT, S.triking and S.ite for tiny and huge pairs, and for shapes 1e-300 or 1e300 apart', function()
    local rng = PRNG.new(SEED + 1)
    local CASES, colliding = 900, 0
    for case = 1, CASES do
      local a, b
      local setup = case % 3
      if setup == 0 then -- a pair from gen, scaled down or up about the origin
        a, b = gen.pair(S, rng, 'any', 'any', case % 2 == 0)
        local k = rng:next() < 0.7 and pow10(rng, -95, -20) or pow10(rng, 20, 95)
        if not (pcall(a.scale, a, k, 0, 0) and pcall(b.scale, b, k, 0, 0)) then a = nil end
      elseif setup == 1 then -- circles and points whose centres are 10^-320 .. 10^-100 apart
        local r = rng:int(0, 3) == 0 and 0 or pow10(rng, -100, 2)
        a = r == 0 and H.Point(0, 0) or H.Circle(0, 0, r)
        local d, t = pow10(rng, -320, -100), rng:range(-pi, pi)
        r = rng:int(0, 1) == 0 and 0 or pow10(rng, -100, 2)
        b = r == 0 and H.Point(d * cos(t), d * sin(t)) or H.Circle(d * cos(t), d * sin(t), r)
        if rng:next() < 0.3 then a:translate(-pow10(rng, 150, 307), 0) end -- (then 1e150 .. 1e307 apart)
      else -- a circle (or point) in a polygon's vertex region, 10^-320 .. 10^0 from the vertex
        a = gen.shape(S, rng, gen.pick(rng, 'poly'), rng:range(-5, 5), rng:range(-5, 5))
        local v, n = a:getVertices()
        local i = rng:int(1, n)
        local h = i > 1 and i - 1 or n
        local n1x, n1y = a:getNormal(h)
        local n2x, n2y = a:getNormal(i)
        local w = rng:next()
        local ux, uy = n1x * w + n2x * (1 - w), n1y * w + n2y * (1 - w)
        local d = pow10(rng, -320, 0) / sqrt(ux * ux + uy * uy)
        local x, y = v[2 * i - 1] + d * ux, v[2 * i] + d * uy
        b = rng:next() < 0.3 and H.Point(x, y) or H.Circle(x, y, pow10(rng, -3, 1))
      end
      if a then
        local function ctx(what, m)
          return ('seed %d case %d: %s normal (%s, %s) is not unit (depth %s); a = %s; b = %s'):format(SEED + 1, case,
            what, g(m.nx), g(m.ny), tostring(m.depth), gen.show(a), gen.show(b))
        end
        for _, order in ipairs({ { a, b }, { b, a } }) do
          local m = S.AT(order[1], order[2])
          assert(isUnit(m.nx, m.ny), ctx('S.AT', m))
          if not m.separating then
            colliding = colliding + 1
            local contacts = S.ite(m)
            if contacts then assert(isUnit(contacts.nx, contacts.ny), ctx('S.ite', contacts)) end
          end
          local mt = S.triking(order[1], order[2])
          if mt then assert(isUnit(mt.nx, mt.ny), ctx('S.triking', mt)) end
        end
      end
    end
    assert.is_true(colliding > CASES / 4, ('only %d colliding pairs'):format(colliding))
  end)

  it('whatever a constructor accepts, at any size, has unit normals; what it refuses is out of range', function()
    local rng = PRNG.new(SEED + 2)
    local accepted, refused = 0, 0
    for case = 1, 700 do
      local sz = pow10(rng, -110, 110)
      local x, y = rng:range(-2, 2) * sz, rng:range(-2, 2) * sz
      local which = case % 8
      local ok, s
      if which == 0 then
        local t = rng:range(-pi, pi)
        ok, s = pcall(H.Edge, x, y, x + sz * cos(t), y + sz * sin(t))
      elseif which == 1 then
        ok, s = pcall(H.Rectangle, x, y, sz, sz * rng:range(0.1, 10), rng:range(-pi, pi))
      elseif which == 2 then
        ok, s = pcall(H.RegularPolygon, x, y, rng:int(3, 64), sz, rng:range(-pi, pi))
      elseif which == 3 then
        ok, s = pcall(H.Ellipse, x, y, sz, sz * rng:range(0.2, 5), rng:int(3, 40))
      elseif which == 4 then
        ok, s = pcall(H.Circle, x, y, sz)
      elseif which == 5 then
        local pts = {}
        for i = 1, 3 do pts[2 * i - 1], pts[2 * i] = x + sz * cos(2 * pi * i / 3), y + sz * sin(2 * pi * i / 3) end
        ok, s = pcall(H.ConvexPolygon, pts)
      elseif which == 6 then
        ok, s = pcall(T.Chain, x, y, x + sz, y, x + sz, y + sz, rng:next() < 0.5)
      else
        ok, s = pcall(T.Capsule, x, y, sz, sz * rng:range(1, 3))
      end
      if ok then
        accepted = accepted + 1
        local leaves = s.getShapeCount and { s:unpack() } or { s }
        for _, leaf in ipairs(leaves) do
          for i = 1, leaf:getVertexCount() do
            local nx, ny = leaf:getNormal(i)
            assert(isUnit(nx, ny), ('seed %d case %d: size %s: normal %d (%s, %s) of %s'):format(SEED + 2, case, g(sz),
              i, g(nx), g(ny), gen.show(leaf)))
          end
          if leaf.isConvex then
            assert(isUnit(leaf[layout.G1X], leaf[layout.G1Y]) and isUnit(leaf[layout.G2X], leaf[layout.G2Y]),
              'chain ghost normals')
          end
        end
      else
        refused = refused + 1
        local err = tostring(s)
        assert(err:find('too small', 1, true) or err:find('too large', 1, true)
          or err:find('non-collinear', 1, true) or err:find('distinct', 1, true),
          ('seed %d case %d: size %s refused with "%s"'):format(SEED + 2, case, g(sz), err))
        assert(sz < 1e-95 or sz > 1e95 or err:find('distinct', 1, true) or err:find('non-collinear', 1, true),
          ('seed %d case %d: size %s, well inside the limits, refused with "%s"'):format(SEED + 2, case, g(sz), err))
      end
    end
    assert.is_true(accepted > 400 and refused > 50, ('%d accepted, %d refused'):format(accepted, refused))
  end)

  it('a transform refuses exactly what the constructor refuses (away from the limits\' rounding)', function()
    local rng = PRNG.new(SEED + 3)
    local agreed = 0
    for case = 1, 700 do
      local w, h, r = pow10(rng, -2, 2), pow10(rng, -2, 2), pow10(rng, -2, 2)
      local k = pow10(rng, -104, 104)
      local which = case % 7
      local function build(f)
        if which == 0 then return pcall(H.Rectangle, 0, 0, w * f, h * f) end
        if which == 1 then return pcall(H.Circle, 0, 0, r * f) end
        if which == 2 then return pcall(H.Edge, 0, 0, w * f, h * f) end
        if which == 3 then return pcall(H.RegularPolygon, 0, 0, 6, r * f) end
        if which == 4 then return pcall(T.Capsule, 0, 0, w * f, (w + h) * f) end
        if which == 5 then return pcall(T.Chain, 0, 0, w * f, 0, w * f, h * f) end
        return pcall(T.Concave, 0, 0, 2 * w * f, 0, 2 * w * f, h * f, w * f, h * f, w * f, 2 * h * f, 0, 2 * h * f)
      end
      local _, base = build(1)
      local direct = build(k)
      local scaled, err = pcall(base.scale, base, k)
      -- the nearest limit the shape's lengths come to, relative (skip rounding's reach)
      local margin = huge
      for _, leaf in ipairs(base.getShapeCount and { base:unpack() } or { base }) do
        local short, radius = leaf[layout.SHORT] * k, leaf[layout.RADIUS] * k
        margin = min(margin, abs(short / 1e-100 - 1), abs(radius / 1e100 - 1))
      end
      if margin > 1e-9 then
        agreed = agreed + 1
        assert(direct == scaled, ('seed %d case %d: built at %s %s, scaled by %s %s (%s)'):format(SEED + 3, case,
          g(k), direct and 'accepted' or 'refused', g(k), scaled and 'accepted' or 'refused', tostring(err)))
        if not scaled then assert.equals(1, (base.getShapeCount and (base:unpack()) or base):getScale()) end
      end
    end
    assert.is_true(agreed > 500)
  end)
end)
