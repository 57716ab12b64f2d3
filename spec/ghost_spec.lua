-- Ghost collisions: bodies sliding along floors made of several pieces must be pushed out
-- of the surface, never back against their motion by an internal joint.
--   Part 1: compound colliders (tile rows, edges end to end) already get this from
--           S.triking's deepest-MTV rule; these specs pin it down.
--   Part 2: S.trikers.Chain, one-sided segments with ghost vertices (Catto, "Ghost
--           Collisions", Box2D blog 2020; Box2D v3 chain segments).
local S = require('strike')
local expect = require('spec.helpers.expect')
local PRNG = require('spec.helpers.prng')
local near, raisesAt = expect.near, expect.raisesAt
local H, T = S.hapes, S.trikers
local chain = require('strike.collide.chain')
local sat = require('strike.collide.sat')
local unpack = table.unpack or unpack -- luacheck: ignore 113 143
local abs, sqrt, max = math.abs, math.sqrt, math.max

local function minX(b) return (b:getBounds()) end
local function maxX(b) local _, _, x = b:getBounds() return x end
-- The centre of a single-shape collider: its shape's pose, which translateTo sets exactly
-- (the collider's own centroid is area-weighted, a * x / a, and may round).
local function midX(b) return ((b:unpack()):getCentroid()) end

-- Move `body` horizontally so that `getX(body)` is exactly `x` when some double allows it
-- (a few translations absorb the rounding of centroid-relative vertices). Returns true
-- when it is exact.
local function placeX(body, x, getX)
  if getX == midX then
    local leaf = (body:unpack())
    leaf:translateTo(x, select(2, leaf:getCentroid()))
    return midX(body) == x
  end
  for _ = 1, 8 do
    local d = x - getX(body)
    if d == 0 then return true end
    body:translate(d, 0)
  end
  return getX(body) == x
end
local function bottom(b) local _, _, _, y = b:getBounds() return y end

-- One step of the drive: put the body at x (by `getX`), sink it by `sink` (y grows
-- downward; the floor is below), resolve with the MTV of S.triking(floor, body) and check
-- it: a collision, pushing up, never sideways by more than `tol`, leaving the body on the
-- surface and not moved back. Returns the MTV and whether the placement was exact.
local out = S.MTV()
local function flatStep(floor, body, x, getX, sink, tol, surfaceY, what)
  local exact = placeX(body, x, getX)
  body:translate(0, sink)
  local m = S.triking(floor, body, out)
  assert(m, what .. ': no collision at x = ' .. x)
  assert(abs(m.x) <= tol, ('%s: sideways MTV %.17g at x = %.17g'):format(what, m.x, x))
  assert(m.y < 0, ('%s: MTV (%.17g, %.17g) does not push up at x = %.17g'):format(what, m.x, m.y, x))
  local before = getX(body)
  body:translate(m.x, m.y)
  assert(getX(body) >= before - tol, ('%s: pushed back at x = %.17g'):format(what, x))
  near(bottom(body), surfaceY, tol, what .. ': resting on the surface at x = ' .. x)
  return m, exact
end

-- Drive `body` (height h) from x0 to x1 along a flat floor whose top is at surfaceY, in
-- steps of `step`; then with its left side, its centre and its right side on each seam,
-- and at the nearest doubles on either side of it. A side cannot always sit exactly on
-- a seam (a side is centre + half-width, rounded: with a 0.8 box, 1.4 + -0.4 is 1 - 2^-53
-- and the next centre gives 1 + 2^-52), so the placements that were exact are counted.
-- Returns the number of steps, the largest |mtv.x|, and the exact placements of the
-- sides and of the centre.
local function driveFlat(floor, body, h, x0, x1, step, seams, surfaceY, tol, what)
  local worst, steps, sides, centres = 0, 0, 0, 0
  local function go(x, getX, label)
    local m, exact = flatStep(floor, body, x, getX, 0.02 * h, tol, surfaceY, what .. label)
    worst, steps = max(worst, abs(m.x)), steps + 1
    return exact
  end
  local k = 0
  while x0 + k * step <= x1 do
    go(x0 + k * step, midX, '')
    k = k + 1
  end
  for _, s in ipairs(seams) do
    local u = abs(s) * 2 ^ -52 -- at least one unit in the last place of s
    for _, getX in ipairs({ minX, midX, maxX }) do
      if go(s, getX, ' (on a seam)') then
        if getX == midX then centres = centres + 1 else sides = sides + 1 end
      end
      go(s - u, getX, ' (just before a seam)')
      go(s + u, getX, ' (just after a seam)')
    end
  end
  return steps, worst, sides, centres
end

describe('Part 1: compound floors, S.triking keeps the deepest MTV', function()
  for _, scale in ipairs({ 1, 1000 }) do
    local tol = 1e-9 * scale
    local tile, size = scale, 0.8 * scale

    it(('a box and a circle slide along a row of 50 tiles without a sideways push (tile %g)'):format(scale), function()
      local tiles = {}
      for i = 0, 49 do tiles[#tiles + 1] = H.Rectangle((i + 0.5) * tile, 0.5 * tile, tile, tile) end
      local floor = T.Collider(unpack(tiles))
      local seams = {}
      for i = 2, 48 do seams[#seams + 1] = i * tile end
      local bodies = {
        box = T.Rectangle(tile, -size / 2, size, size),
        circle = T.Circle(tile, -size / 2, size / 2),
      }
      for name, body in pairs(bodies) do
        local steps, worst, sides, centres = driveFlat(floor, body, size, tile, 49 * tile, tile / 37, seams, 0, tol,
          name)
        assert.is_true(steps > 1800)
        assert.is_true(worst <= tol)
        assert.equals(#seams, centres) -- a centre lands exactly on every seam
        if scale == 1000 then assert.equals(2 * #seams, sides) end -- (integers: exact)
      end
    end)

    it(('a box and a circle slide across two Edges end to end without a sideways push (tile %g)'):format(scale),
      function()
      local floor = T.Collider(H.Edge(0, 0, tile, 0), H.Edge(tile, 0, 2 * tile, 0))
      local box = T.Rectangle(size / 2, -size / 2, size, size)
      local steps, worst, sides, centres = driveFlat(floor, box, size, size / 2, 2 * tile - size / 2, tile / 101,
        { tile }, 0, tol, 'box')
      assert.is_true(steps > 100 and worst <= tol and centres == 1)
      if scale == 1000 then assert.equals(2, sides) end
      local ball = T.Circle(size / 2, -size / 2, size / 2)
      steps, worst, sides, centres = driveFlat(floor, ball, size, size / 2, 2 * tile - size / 2, tile / 101, { tile },
        0, tol, 'ball')
      assert.is_true(steps > 100 and worst <= tol and centres == 1)
      if scale == 1000 then assert.equals(2, sides) end
    end)
  end

  it('the original README example: a box across the joint of two edges is pushed up, never sideways', function()
    local floor = T.Collider(H.Edge(400, 600, 600, 600), H.Edge(600, 600, 800, 600))
    local box = T.Rectangle(425, 575, 50, 50)
    local steps, _, sides, centres = driveFlat(floor, box, 50, 425, 775, 1, { 600 }, 600, 1e-9 * 200, 'box')
    assert.is_true(steps > 350 and sides == 2 and centres == 1)
  end)
end)

-- A chain's segments as a list.
local function segments(c)
  local list = {}
  for s in c:elems() do list[#list + 1] = s end
  return list
end

local function cross(ax, ay, bx, by) return ax * by - ay * bx end

describe('S.trikers.Chain', function()
  it('builds one ChainSegment per consecutive pair of points, with ghost vertices', function()
    local c = T.Chain(0, 0, 10, 0, 20, 5, 30, 5)
    assert.is_true(c:is(T.Collider) and c:is(T.Chain))
    assert.is_false(c:isLoop())
    local seg = segments(c)
    assert.equals(3, #seg)
    local pts = { 0, 0, 10, 0, 20, 5, 30, 5 }
    for i, s in ipairs(seg) do
      assert.equals('chain', s:getKind())
      assert.equals(2, s:getVertexCount())
      local x1, y1, x2, y2 = s:getEdge(1)
      assert.same({ pts[2 * i - 1], pts[2 * i], pts[2 * i + 1], pts[2 * i + 2] }, { x1, y1, x2, y2 })
      local x0, y0, x3, y3 = s:getGhostVertices()
      assert.same({ pts[2 * i - 3], pts[2 * i - 2], pts[2 * i + 3], pts[2 * i + 4] }, { x0, y0, x3, y3 })
    end
    assert.is_nil((seg[1]:getGhostVertices()))
    assert.is_nil(select(3, seg[3]:getGhostVertices()))
    near(c:getArea(), 0)
    -- segments are Edges: a two-sided edge's face 1 normal is the free side's
    local nx, ny = seg[1]:getNormal(1)
    assert.same({ 0, -1 }, { nx, ny })
    assert.is_true(seg[2]:is(H.Edge))
    -- unpack rebuilds a segment, ghost vertices included; copy keeps them
    local ChainSegment = getmetatable(seg[2])
    assert.same({ 10, 0, 20, 5, 0, 0, 30, 5 }, { seg[2]:unpack() })
    assert.same({ seg[2]:unpack() }, { ChainSegment(seg[2]:unpack()):unpack() })
    assert.same({ seg[1]:unpack() }, { ChainSegment(seg[1]:unpack()):unpack() })
    assert.same({ seg[3]:unpack() }, { seg[3]:copy():unpack() })
    assert.equals('chain', seg[3]:copy():getKind())
  end)

  it('closes a loop, from arguments or from one table, and drops duplicate points', function()
    local square = { 0, 0, 10, 0, 10, 10, 0, 10 }
    for _, c in ipairs({ T.Chain(0, 0, 10, 0, 10, 10, 0, 10, true), T.Chain(square, true),
      T.Chain({ 0, 0, 10, 0, 10, 0, 10, 10, 0, 10, 0, 0 }, true) }) do
      assert.is_true(c:isLoop())
      local seg = segments(c)
      assert.equals(4, #seg)
      for i, s in ipairs(seg) do
        local prev, nxt = seg[(i - 2) % 4 + 1], seg[i % 4 + 1]
        local x0, y0, x3, y3 = s:getGhostVertices()
        local px, py = prev:getVertex(1)
        local qx, qy = nxt:getVertex(2)
        assert.same({ px, py, qx, qy }, { x0, y0, x3, y3 })
      end
    end
    assert.equals(3, T.Chain(square):getShapeCount())
    assert.equals(3, T.Chain(square, false):getShapeCount())
    assert.equals(3, T.Chain(0, 0, 10, 0, 10, 10, 0, 10, false):getShapeCount())
    local loop = nil
    assert.equals(3, T.Chain(0, 0, 10, 0, 10, 10, 0, 10, loop):getShapeCount())
    assert.equals(1, T.Chain(0, 0, 0, 0, 5, 5, 5, 5):getShapeCount())
  end)

  it('knows which corners are convex: the free side gets wider there (open ends count as convex)', function()
    -- positive winding (clockwise on a LÖVE screen): every corner of the loop is convex
    local ccw = segments(T.Chain(0, 0, 10, 0, 10, 10, 0, 10, true))
    local area = 0
    for _, s in ipairs(ccw) do
      local x1, y1, x2, y2 = s:getEdge(1)
      area = area + cross(x1, y1, x2, y2)
      assert.is_true(s:isConvex(1) and s:isConvex(2))
      -- the normal points outward: away from the square's centre (5, 5)
      local nx, ny = s:getNormal(1)
      assert.is_true(nx * ((x1 + x2) / 2 - 5) + ny * ((y1 + y2) / 2 - 5) > 0)
    end
    assert.is_true(area > 0)
    for _, s in ipairs(segments(T.Chain(0, 0, 0, 10, 10, 10, 10, 0, true))) do
      assert.is_false(s:isConvex(1) or s:isConvex(2))
    end
    -- y down: a hill (peak) is convex, a valley concave; the ends are convex
    local hill = segments(T.Chain(0, 0, 10, -3, 20, 0))
    assert.is_true(hill[1]:isConvex(1) and hill[1]:isConvex(2) and hill[2]:isConvex(1) and hill[2]:isConvex(2))
    local valley = segments(T.Chain(0, 0, 10, 3, 20, 0))
    assert.is_true(valley[1]:isConvex(1) and valley[2]:isConvex(2))
    assert.is_false(valley[1]:isConvex(2) or valley[2]:isConvex(1))
    assert.is_nil(hill[1]:isConvex(3))
  end)

  it('moves its ghost vertices with every transform, and keeps colliding right', function()
    local c = T.Chain(0, 0, 10, 0, 20, -4, 30, -4)
    local function checkGhosts(what)
      local seg = segments(c)
      for i, s in ipairs(seg) do
        local x0, y0, x3, y3 = s:getGhostVertices()
        if i > 1 then
          local px, py = seg[i - 1]:getVertex(1)
          near(x0, px, 1e-9, what)
          near(y0, py, 1e-9, what)
        end
        if i < #seg then
          local qx, qy = seg[i + 1]:getVertex(2)
          near(x3, qx, 1e-9, what)
          near(y3, qy, 1e-9, what)
        end
      end
    end
    -- a box resting 0.1 deep on the middle of segment 2, square to it
    local function boxOn(seg)
      local x1, y1, x2, y2 = seg:getEdge(1)
      local nx, ny = seg:getNormal(1)
      local cx, cy = (x1 + x2) / 2 + nx * 0.9, (y1 + y2) / 2 + ny * 0.9
      local ex, ey = -ny, nx -- the unit tangent p1 -> p2
      return T.ConvexPolygon(cx - ex - nx, cy - ey - ny, cx + ex - nx, cy + ey - ny, cx + ex + nx, cy + ey + ny,
        cx - ex + nx, cy - ey + ny)
    end
    local transforms = {
      { 'translate', function() c:translate(100, -50) end },
      { 'rotate', function() c:rotate(1.1) end },
      { 'rotate about a point', function() c:rotate(-2.5, 7, 3) end },
      { 'scale', function() c:scale(3) end },
      { 'rotateTo', function() c:rotateTo(0.4, -10, 0) end },
      { 'copy', function() c = c:copy(5, 5, 2) end },
    }
    for _, t in ipairs(transforms) do
      t[2]()
      checkGhosts(t[1])
      local seg = segments(c)[2]
      local nx, ny = seg:getNormal(1)
      local m = S.triking(c, boxOn(seg))
      assert(m, t[1] .. ': no collision')
      near(m.depth, 0.1, 1e-9, t[1] .. ': depth')
      near(m.nx, nx, 1e-9, t[1] .. ': nx')
      near(m.ny, ny, 1e-9, t[1] .. ': ny')
      -- the same box on the far side of the segment passes through
      local below = boxOn(seg):translate(-1.8 * nx, -1.8 * ny)
      assert(not S.triking(c, below), t[1] .. ': the solid side collided')
    end
  end)

  it('is one-sided: a body whose centroid is behind a segment passes through it', function()
    local floor = T.Chain(-50, 0, 50, 0)
    for _, body in ipairs({ T.Rectangle(0, 3, 4, 2), T.Circle(0, 3, 1.5), T.RegularPolygon(0, 3, 3, 1.5) }) do
      local crossed = false
      for _ = 1, 400 do
        body:translate(0, -0.01) -- moving up, from below (the solid side)
        local _, cy = body:getCentroid()
        local m = S.triking(floor, body)
        local m2 = S.triking(body, floor)
        if cy > 0 then
          assert.is_false(m)
          assert.is_false(m2)
        elseif m then
          crossed = true
          assert.is_true(m.ny < 0) -- once over the line it is pushed up, out of the floor
          assert.is_true(m2.ny > 0)
          near(m.depth, m2.depth, 1e-12)
        end
      end
      assert.is_true(crossed)
    end
    local seg = segments(floor)[1]
    local m = S.AT(seg, H.Rectangle(0, 0.5, 4, 2))
    assert.is_true(m.separating)
    assert.equals(0, m.depth)
  end)

  it('removes the ghost collision of a box entering the next segment (an Edge would push it back)', function()
    -- the box (2 wide) has entered segment 2 by 0.05 and is 0.1 deep: as a lone edge,
    -- segment 2 pushes it back by 0.05; as a chain segment, up by 0.1
    local seg2 = segments(T.Chain(0, 0, 10, 0, 20, 0))[2]
    local box = H.Rectangle(9.05, -0.9, 2, 2)
    local plain = S.AT(H.Edge(10, 0, 20, 0), box)
    assert.same({ -1, 0 }, { plain.nx, plain.ny })
    near(plain.depth, 0.05)
    local m = S.AT(seg2, box)
    assert.same({ 0, -1, 1 }, { m.nx, m.ny, m.edgeIndex })
    near(m.depth, 0.1)
    local r = S.AT(box, seg2)
    assert.same({ 0, 1, -1 }, { r.nx, r.ny, r.edgeIndex })
    near(r.depth, 0.1)
    -- a concave corner snaps too: the rising segment pushes along its own normal
    local rise = segments(T.Chain(0, 0, 10, 0, 20, -10))[2]
    m = S.AT(rise, H.Rectangle(9.9, -0.95, 2, 2))
    local nx, ny = rise:getNormal(1)
    near(m.nx, nx)
    near(m.ny, ny)
    assert.is_true(m.depth > 0 and m.edgeIndex == 1)
  end)

  it('pushes a body resting on a convex corner along an admissible normal', function()
    local hill = T.Chain(0, 0, 10, -2, 20, 0)
    local seg = segments(hill)
    -- a level box on the peak: straight up (the corner's cone holds the vertical)
    local m = S.triking(hill, T.Rectangle(10, -2.9, 2, 2))
    assert.same({ 0, -1 }, { m.nx, m.ny })
    near(m.depth, 0.1)
    -- a circle on the peak: along the line from the peak to its centre
    m = S.triking(hill, T.Circle(10.1, -3, 1.2))
    local d = sqrt(0.1 * 0.1 + 1)
    near(m.nx, 0.1 / d)
    near(m.ny, -1 / d)
    near(m.depth, 1.2 - d)
    -- a box tilted between the two slopes: its own face normal
    local a = 0.1
    local box = T.Rectangle(10 - 0.95 * math.sin(a), -2 - 0.95 * math.cos(a), 2, 2, -a)
    m = S.triking(hill, box)
    near(m.nx, -math.sin(a), 1e-9)
    near(m.ny, -math.cos(a), 1e-9)
    for _, s in ipairs(seg) do assert.is_true(chain.admissible(s, m.nx, m.ny)) end
    -- a circle just past the peak, on segment 2: segment 2's face normal; segment 1 (whose
    -- corner cone does not hold the direction to the centre) leaves the contact to it
    local nx, ny = seg[2]:getNormal(1)
    local px, py = 10.05, -1.99 -- on segment 2, just past the peak
    local ball = T.Circle(px + nx * 0.392, py + ny * 0.392, 0.4)
    assert.is_true(S.AT(seg[1], (ball:unpack())).separating)
    assert.is_false(sat.polygonCircle(seg[1], (ball:unpack()), S.MTV()).separating) -- (an Edge would collide)
    m = S.triking(hill, ball)
    near(m.nx, nx)
    near(m.ny, ny)
    near(m.depth, 0.008)
  end)

  it('gives contact points on the segment\'s face for replaced normals (S.ite)', function()
    local seg2 = segments(T.Chain(0, 0, 10, 0, 20, 0))[2]
    local box = H.Rectangle(9.05, -0.9, 2, 2)
    for _, order in ipairs({ { seg2, box }, { box, seg2 } }) do
      local m = S.AT(order[1], order[2])
      local c = S.ite(m)
      assert.equals(2, c.count)
      assert.same({ m.nx, m.ny }, { c.nx, c.ny })
      local xs = { c[1].x, c[2].x }
      table.sort(xs)
      near(xs[1], 10)
      near(xs[2], 10.05)
      for i = 1, 2 do
        near(c[i].y, 0.05) -- midway between the box's bottom (0.1 deep) and the line
        near(c[i].depth, 0.1)
      end
    end
    local ball = S.AT(seg2, H.Circle(12, -0.9, 1))
    local c = S.ite(ball)
    assert.equals(1, c.count)
    near(c[1].x, 12)
    near(c[1].y, 0.05)
  end)

  it('never collides with another chain; works against edges and points', function()
    local a, b = T.Chain(0, 0, 10, 0), T.Chain(5, -1, 5, 1, 6, 1)
    assert.is_false(S.triking(a, b))
    local m = S.AT((a:unpack()), (b:unpack()))
    assert.is_true(m.separating)
    local e = S.triking(a, T.Edge(2, -1, 3, 0.5))
    assert.is_table(e)
    assert.is_true(e.ny < 0)
    assert.is_false(S.triking(a, T.Point(5, -0.5)))
  end)

  it('reports bad arguments at the caller\'s line', function()
    raisesAt(function() T.Chain(0, 0) end, 'strike.Chain: a chain needs at least 2 distinct points, got 1')
    raisesAt(function() T.Chain(0, 0, 0, 0) end, 'strike.Chain: a chain needs at least 2 distinct points, got 1')
    raisesAt(function() T.Chain(0, 0, 5, 5, true) end, 'strike.Chain: a loop needs at least 3 distinct points, got 2')
    raisesAt(function() T.Chain({ 0, 0, 5, 5, 0, 0 }, true) end, 'a loop needs at least 3 distinct points, got 2')
    raisesAt(function() T.Chain() end, 'strike.Chain: a chain needs at least 2 distinct points, got 0')
    raisesAt(function() T.Chain(0, 0, 5) end, 'strike.Chain: expected x, y pairs, got an odd number of values (3)')
    raisesAt(function() T.Chain(0, 0, 5, 0 / 0) end, 'strike.Chain: y2 must be a finite number, got nan')
    raisesAt(function() T.Chain(0, 0, 5, 5, 'yes') end, 'strike.Chain: loop must be a boolean, got string "yes"')
    raisesAt(function() T.Chain({ 0, 0, 5, 5 }, 'yes') end, 'strike.Chain: loop must be a boolean, got string "yes"')
    raisesAt(function() T.Chain({ 0, 0, 5, 5 }, true, 1) end, 'strike.Chain: expected a table of coordinates')
    raisesAt(function() T.Chain({ 0, 0, 5, math.huge }) end, 'strike.Chain: y2 must be a finite number, got inf')
    raisesAt(function() T.Chain(-1e308, 0, 1e308, 0) end, 'strike.Chain: too large: its segment 1 is inf')
    raisesAt(function() T.Chain(0, 0, 1, 0):translate(0 / 0, 0) end, 'must be a finite number')
  end)

  describe('sliding along long chains', function()
    -- Drive `body` (height h) along the chain from x0 to x1 in steps of `step`, sinking
    -- it by 2% of h per step and resolving with S.triking(floor, body). Every step must
    -- collide; no MTV may push against the motion (+x) by more than the local slope
    -- explains: |nx| <= maxSin (the steepest segment's), and the depth at most the sink
    -- plus the rise over this step's horizontal move dx (step, plus what the slope pushed
    -- back the step before), plus what the last resolution left (at a concave corner,
    -- leaving one segment along its normal can leave the body a little inside the other).
    -- A ghost collision fails all three.
    local function drive(floor, body, h, x0, x1, step, maxSin, tol, what)
      local o, rest = S.MTV(), S.MTV()
      body:translate(x0 - midX(body), 0)
      for _ = 1, 10000 do -- settle
        body:translate(0, 0.02 * h)
        if S.triking(floor, body, o) then body:translate(o.x, o.y) break end
      end
      local maxTan = maxSin / sqrt(1 - maxSin * maxSin)
      local worstX, steps, x, left = 0, 0, x0, 0
      while x + step <= x1 do
        x = x + step
        local dx = x - midX(body)
        local budget = 0.02 * h + abs(dx) * maxTan + left
        body:translate(dx, 0.02 * h)
        local m = S.triking(floor, body, o)
        assert(m, ('%s: no collision at x = %.17g'):format(what, x))
        assert(m.ny < 0, ('%s: MTV (%.17g, %.17g) does not push up at x = %.17g'):format(what, m.x, m.y, x))
        assert(abs(m.nx) <= maxSin + 1e-12,
          ('%s: MTV normal (%.17g, %.17g) steeper than any segment at x = %.17g'):format(what, m.nx, m.ny, x))
        assert(m.depth <= budget + tol,
          ('%s: MTV depth %.17g over the budget %.17g at x = %.17g'):format(what, m.depth, budget, x))
        assert(-m.x <= m.depth * maxSin + tol, ('%s: pushed back by %.17g at x = %.17g'):format(what, -m.x, x))
        body:translate(m.x, m.y)
        worstX, steps = max(worstX, -m.x), steps + 1
        left = S.triking(floor, body, rest) and rest.depth or 0
      end
      return steps, worstX
    end

    for _, scale in ipairs({ 1, 1000 }) do
      local tol = 1e-9 * scale
      it(('a box and a circle cross 200 flat segments with a 1e-9 jitter without a backward push (scale %g)')
        :format(scale), function()
        local rng = PRNG.new(PRNG.seedFromEnv(2020))
        local pts = {}
        for i = 0, 200 do
          pts[#pts + 1], pts[#pts + 2] = i * scale, rng:range(-1, 1) * 1e-9 * scale
        end
        local floor = T.Chain(pts)
        local size = 0.8 * scale
        for name, body in pairs({ box = T.Rectangle(0, -size, size, size), circle = T.Circle(0, -size, size / 2) }) do
          local steps, worst = drive(floor, body, size, 2 * scale, 198 * scale, scale / 16, 1e-8, tol, name)
          assert.is_true(steps > 3000)
          assert(worst <= tol, ('%s: backward MTV x %.17g'):format(name, worst))
        end
      end)

      it(('a box and a circle cross 200 bumpy segments, convex and concave corners, without snagging (scale %g)')
        :format(scale), function()
        local seed = PRNG.seedFromEnv(2020)
        local rng = PRNG.new(seed)
        local pts, y, maxSin, convex, concave = {}, 0, 0, 0, 0
        local lastDy
        for i = 0, 200 do
          pts[#pts + 1], pts[#pts + 2] = i * scale, y
          local dy = rng:range(-0.15, 0.15) * scale
          maxSin = max(maxSin, abs(dy) / sqrt(scale * scale + dy * dy))
          if lastDy then
            if dy > lastDy then convex = convex + 1 else concave = concave + 1 end -- (y down)
          end
          y, lastDy = y + dy, dy
        end
        assert.is_true(convex > 50 and concave > 50)
        local floor = T.Chain(pts)
        local size = 0.8 * scale
        local bodies = { box = T.Rectangle(0, -5 * size, size, size), circle = T.Circle(0, -5 * size, size / 2) }
        for name, body in pairs(bodies) do
          local steps = drive(floor, body, size, 2 * scale, 198 * scale, scale / 16, maxSin, tol,
            ('seed %d, %s'):format(seed, name))
          assert.is_true(steps > 3000)
        end
      end)
    end
  end)
end)

-- Allocation, measured as in spec/alloc_spec.lua (KB with the GC stopped, the least of three
-- windows; under 4 KB per window is no allocation per call: 10,000 calls of 16 bytes are 156 KB).
local alloc = require('spec.helpers.alloc')
local function kbPer(fn, n) return alloc.kbPer(fn, n, 2000) end

describe('chain allocation', function()
  setup(alloc.jitOff)
  teardown(alloc.jitOn)

  it('S.triking and S.AT with an out MTV allocate nothing against a Chain, on every path', function()
    local hill = T.Chain(0, 0, 10, -2, 20, 0, 30, 0, 40, 2, 50, 0)
    local o = S.MTV()
    local cases = {
      { 'admitted', T.Rectangle(10, -2.9, 2, 2) },
      { 'circle on a corner', T.Circle(10.1, -3, 1.2) },
      { 'snapped', T.Rectangle(29.05, -0.9, 2, 2) },
      { 'concave corner', T.Circle(40, -0.5, 1) },
      { 'one-sided miss', T.Rectangle(25, 0.5, 4, 2) },
      { 'apart', T.Circle(25, -50, 1) },
    }
    for _, case in ipairs(cases) do
      local body = case[2]
      local kb = kbPer(function()
        S.triking(hill, body, o)
        S.triking(body, hill, o)
        S.AT(select(2, hill:unpack()), (body:unpack()), o)
        S.AT((body:unpack()), select(4, hill:unpack()), o)
      end, 2500)
      assert(kb < 4, ('%s: %.3f KB over 10,000 calls'):format(case[1], kb))
    end
    assert.is_false(S.triking(hill, T.Chain(0, 5, 50, 5)))
  end)
end)
