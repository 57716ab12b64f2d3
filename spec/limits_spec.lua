-- strike's limits on sizes (strike/limits.lua): what constructors refuse, transforms refuse
-- too; whatever is accepted has unit normals, at construction and at run time; rays from
-- far away. Regression specs for the tiny-geometry, overflow and far-ray bugs.
local S = require 'strike'
local expect = require('spec.helpers.expect')
local limits = require('strike.limits')
local ChainSegment = require('strike.base.ChainSegment')

local near, nearList, raisesAt = expect.near, expect.nearList, expect.raisesAt
local H, T = S.hapes, S.trikers
local abs, sqrt = math.abs, math.sqrt

-- |n|^2 within 1e-12 of 1
local function unit(nx, ny, what)
  assert(type(nx) == 'number' and type(ny) == 'number', (what or 'normal') .. ': not numbers')
  assert(abs(nx * nx + ny * ny - 1) <= 1e-12,
    ('%s (%.17g, %.17g) is not a unit vector: |n|^2 = %.17g'):format(what or 'normal', nx, ny, nx * nx + ny * ny))
end

-- every edge normal of a vertex shape is unit
local function unitNormals(s)
  for i = 1, s:getVertexCount() do unit(s:getNormal(i)) end
end

describe('limits', function()
  it('are 1e-100 and 1e100, whose squares and cubes are normal doubles', function()
    assert.equals(1e-100, limits.MIN_LENGTH)
    assert.equals(1e100, limits.MAX_LENGTH)
    local tiny = 2.2250738585072014e-308 -- the smallest normal double
    assert.is_true(limits.MIN_LENGTH ^ 3 > tiny and limits.MAX_LENGTH ^ 3 < math.huge)
  end)

  it('unit and length work for any finite vector', function()
    for _, v in ipairs({ { 1e-320, 0 }, { 5e-324, 5e-324 }, { 1e-200, 3e-200 }, { 1.7e308, 1.7e308 }, { 3, 4 } }) do
      local ux, uy, l = limits.unit(v[1], v[2])
      unit(ux, uy)
      assert.equals(l, limits.length(v[1], v[2]))
    end
    near(limits.length(3e-200, 4e-200), 5e-200, 1e-214)
    assert.equals(math.huge, limits.length(1.7e308, 1.7e308))
    assert.is_nil(limits.unit(0, 0))
    local ux, uy, d = limits.direction(-1.5e308, 0, 1.5e308, 0) -- (the difference overflows)
    nearList({ ux, uy }, { 1, 0 })
    assert.equals(math.huge, d)
  end)
end)

describe('tiny geometry', function()
  it('Edge(0, 0, 1e-200, 0) had a NaN normal; at 1e-160 its normal had length 1.0000056: both refused',
    function()
      raisesAt(function() H.Edge(0, 0, 1e-200, 0) end, 'strike.Edge: too small: its length is 1e-200, below 1e-100')
      raisesAt(function() H.Edge(0, 0, 1e-160, 0) end, 'strike.Edge: too small: its length is 1e-160, below 1e-100')
      raisesAt(function() H.Edge(1e-160, 1e-160, 0, 0) end, 'the smallest length strike accepts')
      raisesAt(function() H.Edge(5e-324, 0, 0, 0) end, 'strike.Edge: too small')
    end)

  it('accepts edges from 1e-100 up, with unit normals', function()
    for _, e in ipairs({ H.Edge(0, 0, 1e-100, 0), H.Edge(0, 0, 1e-100, 1e-100), H.Edge(1e-100, 0, 0, 3e-100),
      H.Edge(0, 0, 1e-100, 0):rotate(1), H.Edge(0, 0, 1, 0):scale(1e-100) }) do
      unitNormals(e)
    end
    nearList({ H.Edge(0, 0, 1e-100, 0):getNormal(1) }, { 0, -1 }, 0)
  end)

  it('ConvexPolygon refuses tiny edges between distinct points and tiny whole polygons', function()
    raisesAt(function() H.ConvexPolygon(0, 0, 1e-200, 0, 1, 1) end,
      'strike.ConvexPolygon: too small: its shortest edge is 1e-200, below 1e-100')
    raisesAt(function() H.ConvexPolygon(0, 0, 1e-200, 0, 0, 1e-200) end, 'strike.ConvexPolygon: too small')
    raisesAt(function() H.ConvexPolygon(0, 0, 1e-101, 0, 0, 1e-101) end, 'strike.ConvexPolygon: too small')
    raisesAt(function() H.ConvexPolygon({ 0, 0, 1e-160, 0, 1e-160, 1e-160 }) end, 'strike.ConvexPolygon: too small')
    unitNormals(H.ConvexPolygon(0, 0, 1e-100, 0, 0, 1e-100))
    unitNormals(H.ConvexPolygon(0, 0, 1, 0, 1, 1e-120, 0, 1)) -- (the hull drops the near-collinear corner)
  end)

  it('Rectangle, RegularPolygon and Ellipse refuse what is too small, naming themselves', function()
    raisesAt(function() H.Rectangle(0, 0, 1e-200) end, 'strike.Rectangle: too small')
    raisesAt(function() H.Rectangle(0, 0, 1e-101, 1e-101) end, 'strike.Rectangle: too small')
    raisesAt(function() H.RegularPolygon(0, 0, 5, 1e-120) end, 'strike.RegularPolygon: too small')
    raisesAt(function() H.RegularPolygon(0, 0, 4096, 1e-98) end, 'strike.RegularPolygon: too small: its shortest edge')
    raisesAt(function() H.Ellipse(0, 0, 1e-120, 1e-120) end, 'strike.Ellipse: too small')
    unitNormals(H.Rectangle(0, 0, 1e-100))
    unitNormals(H.Rectangle(0, 0, 1e-100, 3e-100, 0.3))
    unitNormals(H.RegularPolygon(0, 0, 7, 1e-99, 1))
    unitNormals(H.Ellipse(0, 0, 3e-99, 1e-99, 16))
  end)

  it('Circle refuses radii below 1e-100; Capsule its caps and its straight part', function()
    raisesAt(function() H.Circle(0, 0, 1e-160) end, 'strike.Circle: radius too small: got 1e-160, below 1e-100')
    raisesAt(function() H.Circle(0, 0, 5e-324) end, 'strike.Circle: radius too small')
    raisesAt(function() T.Circle(0, 0, 1e-101) end, 'strike.Circle: radius too small')
    assert.equals(1e-100, H.Circle(0, 0, 1e-100):getRadius())
    raisesAt(function() T.Capsule(0, 0, 1e-200, 1) end, 'strike.Capsule: width (twice the caps\' radius) too small')
    raisesAt(function() T.Capsule(0, 0, 1e-99, 1e-99 + 1e-110) end, 'strike.Capsule: straight part')
    assert.equals(1, T.Capsule(0, 0, 1e-99, 1e-99):getShapeCount())
    assert.equals(3, T.Capsule(0, 0, 1e-99, 2e-99):getShapeCount())
  end)

  it('Chain and ChainSegment refuse tiny segments, ghost segments included', function()
    raisesAt(function() T.Chain(0, 0, 1e-120, 0, 1, 1) end, 'strike.Chain: too small: its segment 1 is 1e-120')
    raisesAt(function() T.Chain({ 0, 0, 1, 0, 1, 1e-150 }, true) end, 'strike.Chain: too small: its segment 2 is')
    raisesAt(function() ChainSegment(0, 0, 1e-200, 0) end, 'strike.ChainSegment: too small: its length is 1e-200')
    raisesAt(function() ChainSegment(0, 0, 1, 0, -1e-120, 0) end, 'strike.ChainSegment: too small: its previous')
    raisesAt(function() ChainSegment(0, 0, 1, 0, nil, nil, 1, 1e-130) end, 'its next segment')
    local c = T.Chain({ 0, 0, 1e-100, 0, 1e-100, 1e-100, 0, 1e-100 }, true)
    for s in c:elems() do
      unitNormals(s)
      unit(s._g1x, s._g1y, 'ghost normal 1')
      unit(s._g2x, s._g2y, 'ghost normal 2')
    end
  end)

  it('Concave refuses outlines whose pieces would be too small, naming itself', function()
    raisesAt(function() T.Concave(0, 0, 2e-120, 0, 2e-120, 2e-120, 1e-120, 1e-120, 0, 2e-120) end,
      'strike.Concave: too small')
    raisesAt(function() T.Concave(0, 0, 2e-150, 0, 2e-150, 2e-150, 1e-150, 1e-150, 0, 2e-150) end,
      'strike.Concave')
    local c = T.Concave(0, 0, 2e-99, 0, 2e-99, 2e-99, 1e-99, 1e-99, 0, 2e-99)
    for s in c:elems() do unitNormals(s) end
  end)

  it('scaling a shape below the limits is refused like building it, and leaves it as it was', function()
    local r = H.Rectangle(0, 0, 1)
    raisesAt(function() r:scale(1e-200) end,
      'strike.Shape:scale: the result would be too small: its shortest edge would be 1e-200, below 1e-100')
    assert.equals(1, r:getScale())
    assert.equals(1, r:getArea())
    raisesAt(function() H.Rectangle(0, 0, 1e-200) end, 'strike.Rectangle: too small')
    r:scale(1e-100) -- (at the limit: accepted, as Rectangle(0, 0, 1e-100) is)
    unitNormals(r)
    raisesAt(function() r:scale(0.5) end, 'strike.Shape:scale: the result would be too small')
    local c = H.Circle(0, 0, 1)
    raisesAt(function() c:scale(1e-101) end, 'strike.Shape:scale: the result would be too small: its radius would be')
    raisesAt(function() H.Circle(0, 0, 1e-101) end, 'strike.Circle: radius too small')
    c:scale(1e-100)
    raisesAt(function() H.Edge(0, 0, 1, 0):scale(1e-200, 5, 5) end, 'strike.Shape:scale: the result would be too small')
  end)

  it('scaling a collider below the limits is refused and moves none of its shapes', function()
    local c = T.Collider(H.Rectangle(5, 0, 1), H.Circle(-5, 0, 1), H.Point(0, 9))
    raisesAt(function() c:scale(1e-200) end, 'strike.Collider:scale: the result would be too small')
    nearList({ c.shapes[1]:getCentroid() }, { 5, 0 }, 0)
    assert.equals(1, c.shapes[1]:getScale())
    raisesAt(function() T.Capsule(0, 0, 1, 3):scale(1e-101) end, 'strike.Collider:scale: the result would be too small')
    raisesAt(function() T.Chain(0, 0, 1, 0, 2, 1):scale(1e-200) end, 'strike.Collider:scale: the result would be')
    raisesAt(function() T.Concave(0, 0, 2, 0, 2, 2, 1, 1, 0, 2):scale(1e-101) end, 'strike.Collider:scale')
  end)

  it('points have no length: they scale and move freely', function()
    local p = H.Point(1, 0):scale(1e-200, 0, 0)
    nearList({ p:getCentroid() }, { 1e-200, 0 }, 0)
    raisesAt(function() H.Point(0, 0):scale(1e-200):scale(1e-200):scale(1e-200) end, 'the scale would underflow to 0')
    raisesAt(function() H.Point(0, 0):scale(1e200):scale(1e200) end, 'strike.Shape:scale: the scale would overflow')
  end)
end)

describe('unit normals at run time', function()
  local function mtvUnit(m, what)
    unit(m.nx, m.ny, what)
    return m
  end

  it('two circles 1e-160 apart (nx was 1.0000056)', function()
    local m = mtvUnit(S.AT(H.Circle(0, 0, 1), H.Circle(1e-160, 0, 1)))
    nearList({ m.nx, m.ny, m.depth }, { 1, 0, 2 }, 1e-15)
    m = mtvUnit(S.AT(H.Circle(0, 0, 1e-100), H.Circle(1e-160, 1e-160, 1e-100)))
    nearList({ m.nx, m.ny }, { sqrt(0.5), sqrt(0.5) }, 1e-15)
    local contacts = S.ite(m)
    unit(contacts.nx, contacts.ny, 'S.ite')
    m = mtvUnit(S.triking(T.Circle(0, 0, 1), T.Circle(-3e-170, 4e-170, 1)))
    nearList({ m.nx, m.ny }, { -0.6, 0.8 }, 1e-15)
  end)

  it('points and circles scaled down with scale(1e-200), or a point against a circle', function()
    local a, b = H.Point(0, 0), H.Point(1, 1):scale(1e-200, 0, 0)
    local m = mtvUnit(S.AT(a, b))
    nearList({ m.nx, m.ny }, { sqrt(0.5), sqrt(0.5) }, 1e-15)
    assert.is_true(m.separating)
    m = mtvUnit(S.AT(H.Point(0, 0), H.Point(-1e-300, 1e-300)))
    nearList({ m.nx, m.ny }, { -sqrt(0.5), sqrt(0.5) }, 1e-15)
    m = mtvUnit(S.AT(H.Point(0, 0), H.Circle(1e-160, 1e-160, 1)))
    assert.is_false(m.separating)
    nearList({ m.nx, m.ny, m.depth }, { sqrt(0.5), sqrt(0.5), 1 }, 1e-15)
    unit(S.ite(m).nx, S.ite(m).ny, 'S.ite')
    m = mtvUnit(S.AT(H.Circle(1e-160, 1e-160, 1), H.Point(0, 0)))
    nearList({ m.nx, m.ny }, { -sqrt(0.5), -sqrt(0.5) }, 1e-15)
    -- the same circles scaled about a common point: their distance scales, their radii too
    local c1, c2 = H.Circle(0, 0, 1e50), H.Circle(3e50, 4e50, 1e50)
    c1:scale(1e-149, 0, 0)
    c2:scale(1e-149, 0, 0)
    m = mtvUnit(S.AT(c1, c2))
    nearList({ m.nx, m.ny }, { 0.6, 0.8 }, 1e-15)
  end)

  it('a circle in a polygon\'s vertex region 1e-160 from the vertex (sat.lua divided by an underflowed sqrt)',
    function()
      local box = H.Rectangle(-1, -1, 2) -- a vertex at (0, 0)
      local m = mtvUnit(S.AT(box, H.Circle(1e-160, 2e-160, 1)))
      nearList({ m.nx, m.ny }, { 1 / sqrt(5), 2 / sqrt(5) }, 1e-15)
      assert.equals(0, m.edgeIndex)
      unit(S.ite(m).nx, S.ite(m).ny, 'S.ite')
      m = mtvUnit(S.AT(H.Circle(3e-200, 4e-200, 1), box))
      nearList({ m.nx, m.ny }, { -0.6, -0.8 }, 1e-15)
      m = mtvUnit(S.triking(T.Circle(1e-300, -1e-300, 0.5), T.Rectangle(-1, 1, 2)))
      nearList({ m.nx, m.ny }, { -sqrt(0.5), sqrt(0.5) }, 1e-15)
    end)

  it('shapes so far apart that the square of their distance overflows (the normal was (0, 0))', function()
    local m = mtvUnit(S.AT(H.Edge(0, 0, 1, 0), H.Circle(1e300, 0, 1)))
    nearList({ m.nx, m.ny }, { 1, 0 })
    assert.is_true(m.separating)
    m = mtvUnit(S.AT(H.Circle(-1e300, 0, 1), H.Circle(1e300, 0, 1)))
    nearList({ m.nx, m.ny }, { 1, 0 })
    m = mtvUnit(S.AT(H.Circle(-1.5e308, 0, 1), H.Circle(1.5e308, 0, 1))) -- (their difference overflows)
    nearList({ m.nx, m.ny }, { 1, 0 })
    assert.equals(-math.huge, m.depth)
    m = mtvUnit(S.AT(H.Point(1e200, 1e200), H.Point(-1e200, -1e200)))
    nearList({ m.nx, m.ny }, { -sqrt(0.5), -sqrt(0.5) }, 1e-15)
  end)

  it('MTVs made by hand from tiny or huge vectors', function()
    local m = S.MTV(1e-200, 0)
    nearList({ m.nx, m.ny }, { 1, 0 }, 0)
    unit(S.MTV(1e-160, 1e-160).nx, S.MTV(1e-160, 1e-160).ny)
    unit(S.MTV(1e308, -1e308).nx, S.MTV(1e308, -1e308).ny)
    near(S.MTV(3e-200, 4e-200):mag(), 5e-200, 1e-214)
    nearList({ S.MTV().nx, S.MTV().ny }, { 0, 0 }, 0)
  end)
end)

describe('overflow', function()
  it('scale(1e300) gave an infinite area where the same rectangle built directly is refused', function()
    local r = H.Rectangle(0, 0, 1)
    raisesAt(function() r:scale(1e300) end, 'strike.Shape:scale: the result would be too large: its radius')
    assert.equals(1, r:getArea())
    assert.equals(1, r:getScale())
    raisesAt(function() H.Rectangle(0, 0, 1e300) end, 'strike.Rectangle: too large')
    -- the limit is the same both ways
    raisesAt(function() r:scale(1e101) end, 'strike.Shape:scale: the result would be too large')
    raisesAt(function() H.Rectangle(0, 0, 1e101) end, 'strike.Rectangle: too large')
    near(H.Rectangle(0, 0, 1e99):getArea(), 1e198, 1e183)
    near(r:scale(1e99):getArea(), 1e198, 1e183)
    raisesAt(function() H.Circle(0, 0, 1):scale(1e101) end, 'strike.Shape:scale: the result would be too large')
    raisesAt(function() H.Circle(0, 0, 1e101) end, 'strike.Circle: radius too large: got 1e+101, above 1e+100')
    raisesAt(function() H.Edge(0, 0, 1, 0):scale(3e100) end, 'strike.Shape:scale: the result would be too large')
    raisesAt(function() H.Edge(0, 0, 3e100, 0) end, 'strike.Edge: too large')
    assert.is_true(H.Edge(0, 0, 1, 0):scale(1e100):getLength() == 1e100)
    raisesAt(function() H.RegularPolygon(0, 0, 6, 1e120) end, 'strike.RegularPolygon: too large')
    raisesAt(function() H.Ellipse(0, 0, 1e150, 1) end, 'strike.Ellipse: too large')
    raisesAt(function() T.Capsule(0, 0, 1, 1e300) end, 'strike.Capsule: height too large')
    raisesAt(function() T.Chain(0, 0, 1e150, 0) end, 'strike.Chain: too large: its segment 1')
    raisesAt(function() T.Concave(0, 0, 2e150, 0, 2e150, 2e150, 1e150, 1e150, 0, 2e150) end, 'strike.Concave')
  end)

  it('coordinates: constructors refuse what translate refuses', function()
    raisesAt(function() H.Point(1e308, 1e308) end, 'strike.Point: coordinates too large')
    raisesAt(function() H.Point(1e308, 0):translate(0, 1e308) end, 'strike.Shape:translate: the result would overflow')
    raisesAt(function() H.Circle(1e308, 1e308, 1) end, 'strike.Circle: coordinates too large')
    raisesAt(function() H.Circle(0, 0, 1):translateTo(1e308, 1e308) end, 'strike.Shape:translateTo: the result would')
    local p = H.Point(1.5e308, 0)
    raisesAt(function() p:rotate(math.pi / 4, 0, 0) end, 'strike.Shape:rotate: the result would overflow')
    nearList({ p:getCentroid() }, { 1.5e308, 0 }, 0)
  end)

  it('colliders refuse a transform that would take any shape out of range, and move none', function()
    local c = T.Collider(H.Rectangle(0, 0, 1), H.Circle(10, 0, 1))
    raisesAt(function() c:scale(1e300) end, 'strike.Collider:scale: the result would be too large')
    raisesAt(function() c:scale(1e101, 0, 0) end, 'strike.Collider:scale: the result would be too large')
    raisesAt(function() c:translate(1.7e308, 1.7e308) end, 'strike.Collider:translate: the result would overflow')
    raisesAt(function() c:translateTo(1.7e308, 1.7e308) end, 'strike.Collider:translateTo: the result would overflow')
    raisesAt(function() c:rotate(math.pi, 1e308, 1e308) end, 'strike.Collider:rotate: the result would overflow')
    nearList({ c.shapes[2]:getCentroid() }, { 10, 0 }, 0)
    assert.equals(1, c.shapes[1]:getScale())
    near(c:getArea(), 1 + math.pi, 1e-12)
    raisesAt(function() T.Capsule(0, 0, 1, 3):scale(1e101) end, 'strike.Collider:scale: the result would be too large')
  end)
end)
