-- Rounded shapes: capsules, rounded rectangles and polygons (a core and a radius), exact
-- in every query. Expected values are worked out by hand in the comments.
local S = require('strike')
local expect = require('spec.helpers.expect')
local near, nearList, raisesAt = expect.near, expect.nearList, expect.raisesAt
local H, T = S.hapes, S.trikers
local pi, sqrt = math.pi, math.sqrt

describe('S.hapes.Capsule', function()
  it('is one rounded shape: a segment swept by a circle', function()
    local c = H.Capsule(1, 2, 10, 30) -- core (1, -8) to (1, 12), radius 5
    assert.equals('rounded', c:getKind())
    assert.equals(5, c:getRounding())
    near(c:getArea(), pi * 25 + 10 * 20)
    nearList({ c:getBbox() }, { -4, -13, 10, 30 })
    nearList({ c:getCentroid() }, { 1, 2 })
    nearList({ c:getDimensions() }, { 10, 30 })
    nearList({ c:unpack() }, { 1, 2, 10, 30, 0 })
    nearList(c:getVertices(), { 1, -8, 1, 12 })
    near(c:getRadius(), 15) -- (centre to the farthest point)
    nearList({ c:project(1, 0) }, { -4, 6 })
  end)

  it('contains the points nearer than its radius to the core, strictly', function()
    local c = H.Capsule(0, 0, 10, 30)
    assert.is_true(c:containsPoint(4.9, 0))
    assert.is_false(c:containsPoint(5, 0)) -- (on the side: touching is not inside)
    assert.is_true(c:containsPoint(0, 14.9))
    assert.is_false(c:containsPoint(0, 15))
    -- beyond the cap's corner region: (4, 14) is sqrt(16 + 16) = 5.66 from (0, 10)
    assert.is_false(c:containsPoint(4, 14))
    assert.is_true(c:containsPoint(3, 13)) -- (sqrt(9 + 9) = 4.24)
  end)

  it('is a disc when the height equals the width, and turns by its angle', function()
    local d = H.Capsule(0, 0, 4, 4)
    near(d:getArea(), 4 * pi)
    local m = S.AT(d, H.Circle(3, 0, 2)) -- centres 3 apart, radii 2 + 2
    near(m.depth, 1)
    nearList({ m.nx, m.ny }, { 1, 0 })
    local turned = H.Capsule(0, 0, 2, 10, pi / 2) -- lying: core (-4, 0) to (4, 0)
    nearList({ turned:getBbox() }, { -5, -1, 10, 2 }, 1e-12)
    near(turned:getAngle(), pi / 2)
  end)

  it('refuses bad sizes at the caller\'s line', function()
    raisesAt(function() H.Capsule(0, 0, 10, 5) end, 'strike.Capsule: height (caps included) must be at least the width')
    raisesAt(function() H.Capsule(0, 0, -1, 5) end, 'strike.Capsule: width must be a finite number > 0, got -1')
    raisesAt(function() H.Capsule(0, 0, 1, 0 / 0) end, 'strike.Capsule: height must be a finite number > 0')
  end)

  it('copies stay rounded (their own kind, not the class\'s)', function()
    local r = H.Rectangle(0, 0, 10, 10, 0.3, 2):copy(5, 5)
    assert.equals('rounded', r:getKind())
    assert.equals(2, r:getRounding())
    local cap = T.Capsule(0, 0, 2, 10):copy(3, 3, 1)
    assert.equals('rounded', (cap:unpack()):getKind())
    -- (a sharp copy would collide with a circle at its box's corner)
    assert.is_false(S.triking(H.Rectangle(0, 0, 10, 10, 0, 2):copy(0, 0), T.Circle(5.5, 5.5, 1)))
  end)

  it('S.trikers.Capsule holds one such shape', function()
    local c = T.Capsule(0, 0, 10, 30, 0.5)
    assert.equals(1, c:getShapeCount())
    assert.equals('rounded', (c:unpack()):getKind())
    near(c:getArea(), pi * 25 + 200)
    nearList({ c:getDimensions() }, { 10, 30 })
    near(c:getAngle(), 0.5)
  end)
end)

describe('rounded rectangles and polygons', function()
  it('a rounded Rectangle still spans w by h, with quarter discs at the corners', function()
    local r = H.Rectangle(0, 0, 10, 10, 0, 2) -- core [-3, 3]^2
    assert.equals('rounded', r:getKind())
    near(r:getArea(), 100 - (4 - pi) * 4)
    nearList({ r:getBbox() }, { -5, -5, 10, 10 })
    nearList(r:getVertices(), { -3, -3, 3, -3, 3, 3, -3, 3 })
    nearList({ r:unpack() }, { 0, 0, 10, 10, 0, 2 })
    assert.is_false(r:containsPoint(4.9, 4.9)) -- (in the box, outside the rounded corner)
    assert.is_true(r:containsPoint(4.9, 0))
    assert.is_true(r:containsPoint(4.4, 4.4)) -- (1.4 * sqrt(2) = 1.98 from the core's corner)
    raisesAt(function() H.Rectangle(0, 0, 10, 4, 0, 2) end,
      'strike.Rectangle: radius must be below half the shorter side')
    raisesAt(function() H.Rectangle(0, 0, 10, 4, 0, -1) end, 'strike.Rectangle: radius must be a finite number > 0')
  end)

  it('ConvexPolygon{..., radius = r} grows the polygon by r (the Steiner formula)', function()
    local p = H.ConvexPolygon({ 0, 0, 10, 0, 0, 10, radius = 1 })
    near(p:getArea(), 50 + (20 + sqrt(200)) + pi)
    nearList({ p:getBbox() }, { -1, -1, 12, 12 })
    nearList(p:getVertices(), { 0, 0, 10, 0, 0, 10 }, 1e-12)
    assert.is_true(p:containsPoint(-0.5, 5))
    assert.is_false(p:containsPoint(-0.70, -0.72)) -- (1.004 from the corner (0, 0))
    raisesAt(function() H.ConvexPolygon({ 0, 0, 1, 0, 0, 1, radius = 'big' }) end,
      'strike.ConvexPolygon: radius must be a finite number > 0')
    -- unpack gives the arguments that rebuild it: the table form, radius included
    p:translate(2, 3):scale(2)
    local again = H.ConvexPolygon(p:unpack())
    near(again:getRounding(), 2)
    near(again:getArea(), p:getArea())
    nearList({ again:getBbox() }, { p:getBbox() })
    assert.equals(1, select('#', p:unpack()))
  end)

  it('its centroid is the area centroid of the grown shape (against a fine grid)', function()
    local p = H.ConvexPolygon({ 0, 0, 10, 0, 0, 10, radius = 2 })
    -- independent: sample the plane on a grid and keep what is within 2 of the triangle
    local function distToTriangle(x, y)
      if x >= 0 and y >= 0 and x + y <= 10 then return 0 end
      local function seg(x1, y1, x2, y2)
        local ex, ey = x2 - x1, y2 - y1
        local t = math.max(0, math.min(1, ((x - x1) * ex + (y - y1) * ey) / (ex * ex + ey * ey)))
        local dx, dy = x - x1 - t * ex, y - y1 - t * ey
        return sqrt(dx * dx + dy * dy)
      end
      return math.min(seg(0, 0, 10, 0), seg(10, 0, 0, 10), seg(0, 10, 0, 0))
    end
    local h, area, mx, my = 0.05, 0, 0, 0
    for i = 0, 320 do
      for j = 0, 320 do
        local x, y = -2.5 + (i + 0.5) * h, -2.5 + (j + 0.5) * h
        if x <= 13 and y <= 13 and distToTriangle(x, y) < 2 then
          area, mx, my = area + h * h, mx + x * h * h, my + y * h * h
        end
      end
    end
    near(p:getArea(), area, 0.05)
    local cx, cy = p:getCentroid()
    near(cx, mx / area, 2e-3)
    near(cy, my / area, 2e-3)
    near(cx, cy, 1e-12) -- (symmetric about y = x)
  end)
end)

describe('rounded collisions', function()
  it('cores overlapping: the SAT depth plus the radii, along the face', function()
    local cap = H.Capsule(0, 0, 10, 30) -- spans y [-15, 15]
    local m = S.AT(cap, H.Rectangle(0, 19, 40, 10)) -- box spans y [14, 24]
    nearList({ m.x, m.y, m.depth }, { 0, 1, 1 })
    assert.equals(-1, m.edgeIndex) -- (the box's face 1, its min-y side)
    local m2 = S.AT(H.Rectangle(0, 19, 40, 10), cap)
    nearList({ m2.x, m2.y, m2.depth }, { 0, -1, 1 })
    -- crossing capsules: cores (-8, 0)-(8, 0) and (0, -2)-(0, 14), radii 2: the second's
    -- core end must rise from -2 to 4, 6 along +y (12 along x, 18 along -y)
    local m3 = S.AT(H.Capsule(0, 0, 4, 20, pi / 2), H.Capsule(0, 6, 4, 20))
    nearList({ m3.x, m3.y, m3.depth }, { 0, 6, 6 }, 1e-9)
  end)

  it('cores apart: the rounded corners meet along the line between the nearest points', function()
    local r = H.Rectangle(0, 0, 10, 10, 0, 2) -- core corner (3, 3)
    -- a sharp box whose corner is at (4.5, 4.5): 1.5 sqrt(2) = 2.12 from (3, 3), beyond 2
    assert.is_true(S.AT(r, H.Rectangle(9.5, 9.5, 10, 10)).separating)
    -- corner at (4, 4): sqrt(2) away, depth 2 - sqrt(2) along (1, 1) / sqrt(2)
    local m = S.AT(r, H.Rectangle(9, 9, 10, 10))
    near(m.depth, 2 - sqrt(2))
    nearList({ m.nx, m.ny }, { 1 / sqrt(2), 1 / sqrt(2) })
    assert.equals(0, m.edgeIndex)
    local c = S.ite(m) -- one point, midway between the corner's arc and the box's corner
    assert.equals(1, c.count)
    local mid = 3 + (2 / sqrt(2) + 1) / 2 -- (3 + sqrt(2), then halfway to 4)
    nearList({ c[1].x, c[1].y, c[1].depth }, { mid, mid, 2 - sqrt(2) })
    -- a circle against the rounded corner: radii add, 2 + 2 against (5.5, 5.5)'s 2.5 sqrt(2)
    local mc = S.AT(r, H.Circle(5.5, 5.5, 2))
    near(mc.depth, 4 - 2.5 * sqrt(2))
    assert.is_true(S.AT(r, H.Circle(6, 6, 1.5)).separating) -- (3.5 > 4 - 0.5? 4.24 > 3.5)
  end)

  it('a capsule lying on a box touches along a segment: two contact points', function()
    local cap = H.Capsule(0, 0, 2, 10, pi / 2) -- core (-4, 0)-(4, 0), radius 1
    local m = S.AT(cap, H.Rectangle(0, 5.5, 20, 10)) -- box top at y = 0.5: 0.5 deep
    nearList({ m.x, m.y, m.depth }, { 0, 0.5, 0.5 }, 1e-12)
    local c = S.ite(m)
    assert.equals(2, c.count)
    table.sort(c, function(p, q) return p.x < q.x end)
    nearList({ c[1].x, c[1].y, c[1].depth, c[2].x, c[2].y, c[2].depth }, { -4, 0.75, 0.5, 4, 0.75, 0.5 }, 1e-12)
  end)

  it('rays meet the moved faces and the corner arcs', function()
    local r = H.Rectangle(0, 0, 10, 10, 0, 2)
    nearList({ r:rayCast(-10, 0, 1, 0) }, { 5, -5, 0, -1, 0 })
    -- at y = 4.5 the ray meets the arc about (-3, 3): x = -3 - sqrt(4 - 1.5^2)
    local x = -3 - sqrt(1.75)
    nearList({ r:rayCast(-10, 4.5, 1, 0) }, { x + 10, x, 4.5, (x + 3) / 2, 0.75 })
    -- down at x = 4.9, past where a sharp corner would be (y = 5), to the arc about (3, 3)
    nearList({ r:rayCast(4.9, 10, 0, -1) }, { 7 - sqrt(0.39), 4.9, 3 + sqrt(0.39), 0.95, sqrt(0.39) / 2 })
    local cap = H.Capsule(0, 0, 10, 30)
    nearList({ cap:rayCast(0, -40, 0, 1) }, { 25, 0, -15, 0, -1 })
    nearList({ cap:rayCast(0, 0, 0, 1) }, { 15, 0, 15, 0, 1 }) -- (from inside: the way out)
    nearList(cap:rayIntersections(-10, 0, 1, 0), { 5, 15 })
  end)

  it('a rounded shape resting on a chain gets no push from the chain\'s vertices', function()
    local ground = T.Chain(0, 0, 10, 0, 20, 0, 30, 0)
    for x = 2, 28, 0.5 do
      local box = H.Rectangle(x, -1.5, 4, 4, 0, 1) -- 0.5 into the ground
      local m = S.triking(ground, box)
      assert(m, 'no collision at x = ' .. x)
      near(m.nx, 0, 1e-12, 'x = ' .. x)
      near(m.y, -0.5, 1e-12, 'x = ' .. x)
      -- (the segment's points: 2 where the flat bottom lies on it, 1 where only the box's end is
      -- over it; 0.5 deep, midway between the ground and the box's bottom, y = 0.25)
      local c = S.ite(m)
      local within = x % 10 >= 2 and x % 10 <= 8 -- (the whole box over one segment)
      assert.is_true(c.count == 2 or (c.count == 1 and not within), 'x = ' .. x)
      for i = 1, c.count do nearList({ c[i].y, c[i].depth }, { 0.25, 0.5 }, 1e-12) end
    end
    -- The second segment of a flat chain against a rounded box 0.1 deep whose corner arc
    -- reaches past the segment's start (10, 0): the nearest points give a slanted normal,
    -- which the segment may not push along; it pushes along its own normal by how far the
    -- box reaches behind its line, radius included: 0.1.
    local seg2 = select(2, ground:unpack())
    local box = H.Rectangle(9.3, -0.9, 2, 2, 0, 0.5) -- core x [8.8, 9.8], y [-1.4, -0.4]
    local m = S.AT(seg2, box)
    nearList({ m.nx, m.ny, m.depth }, { 0, -1, 0.1 }, 1e-12)
    assert.equals(1, m.edgeIndex)
  end)
end)
