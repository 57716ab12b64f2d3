-- User-defined shapes and colliders, as a game would write them: the original Strike README's
-- walkthroughs, and the trapezoid of docs/extending.md in its first form (that guide's own
-- blocks run in spec/docs_examples_spec.lua).
local S = require('strike')
local expect = require('spec.helpers.expect')
local near, nearList, raisesAt = expect.near, expect.nearList, expect.raisesAt
local layout = require('strike.base.layout')
local pi = math.pi

describe('a user-defined shape', function()
  -- The Rectangle walkthrough, line for line (with `x, y` spelled as the nils they are).
  local Rect = S.hapes.ConvexPolygon:extend()
  function Rect:new(x, y, dx, dy, angle)
    assert(dx, 'Rectangle constructor missing width/height')
    dy = dy or dx
    self.dx, self.dy = dx, dy
    self.angle = angle or 0
    local hx, hy = dx / 2, dy / 2
    Rect.super.new(self,
      x - hx, y - hy,
      x + hx, y - hy,
      x + hx, y + hy,
      x - hx, y + hy
    )
    self:rotate(self.angle)
  end
  function Rect:unpack()
    local cx, cy = self:getCentroid(nil, nil)
    return cx, cy, self.dx, self.dy, self.angle
  end

  -- A trapezoid whose (x, y) is its box's centre (docs/extending.md's places its centroid there).
  local Trapezoid = S.hapes.ConvexPolygon:extend()
  function Trapezoid:new(x, y, top, bottom, height)
    self.top, self.bottom, self.height = top, bottom, height
    local h = height / 2
    Trapezoid.super.new(self, x - bottom / 2, y + h, x + bottom / 2, y + h, x + top / 2, y - h, x - top / 2, y - h)
  end
  function Trapezoid:unpack()
    local cx, cy = self:getCentroid()
    return cx, cy, self.top, self.bottom, self.height
  end

  it('works with the walkthrough as written', function()
    local r = Rect(0, 0, 4, 2, pi / 2)
    nearList({ r:getBbox() }, { -1, -2, 2, 4 })
    near(r:getAngle(), pi / 2) -- the walkthrough's self.angle does not double the rotation
    assert.equals(8, r:getArea())
    nearList({ r:unpack() }, { 0, 0, 4, 2, pi / 2 })
  end)

  it('registers by assignment, which also makes the single-shape collider', function()
    S.hapes.Trapezoid = Trapezoid
    assert.equals(Trapezoid, S.hapes.Trapezoid)
    assert.equals('Trapezoid', Trapezoid.name)
    local c = S.trikers.Trapezoid(0, 0, 2, 6, 2)
    assert.is_true(c:is(S.trikers.Collider))
    assert.equals(Trapezoid, getmetatable((c:unpack())))
    near(c:getArea(), 8)
    assert.truthy(S.triking(c, S.trikers.Circle(0, 0, 1)))
  end)

  it('copies, keeping its class and pose', function()
    local t = Trapezoid(0, 0, 2, 6, 2):rotate(0.5):scale(2)
    local k = t:copy()
    assert.equals(Trapezoid, getmetatable(k))
    nearList((k:getVertices()), (t:getVertices()))
    local moved = t:copy(10, 10, 0)
    nearList({ moved:getCentroid() }, { 10, 10 })
    near(moved:getAngle(), 0)
    assert.equals(6, (S.trikers.Collider(t):copy():unpack()).bottom)
  end)

  it('re-registering a name replaces its single-shape collider', function()
    local Other = S.hapes.ConvexPolygon:extend()
    function Other:new(x, y) Other.super.new(self, x, y, x + 1, y, x, y + 1) end
    S.hapes.Wedge = Trapezoid
    local _ = S.trikers.Wedge(0, 0, 2, 6, 2)
    S.hapes.Wedge = Other
    assert.equals(Other, getmetatable((S.trikers.Wedge(0, 0):unpack())))
  end)

  it('registering something that is not a shape class is an error', function()
    raisesAt(function() S.hapes.Bad = {} end, 'S.hapes.Bad must be a class extending a strike shape')
    raisesAt(function() S.hapes.Bad = S.hapes.Circle(0, 0, 1) end, 'got table')
    raisesAt(function() S.hapes[1] = Trapezoid end, 'S.hapes names must be identifiers, got 1')
    raisesAt(function() S.trikers.Bad = Trapezoid end, 'S.trikers.Bad must be a class extending S.trikers.Collider')
  end)
end)

describe('a single-shape collider of a registered class', function()
  -- (S.trikers.X builds its shape and takes it without the checks of Collider:add, which a
  -- shape built a moment ago passes: colliders/Collider.lua, _newSingle; one that would fail
  -- them goes through Collider:add, with its errors)
  local function triangle(self, x, y) S.hapes.ConvexPolygon.new(self, x, y, x + 1, y, x, y + 1) end

  it('whose shape\'s constructor never built it is an error naming the class', function()
    local Hollow = S.hapes.ConvexPolygon:extend()
    function Hollow:new() end
    S.hapes.SpecHollow = Hollow
    raisesAt(function() local _ = S.trikers.SpecHollow(0, 0) end, 'argument 1 (a SpecHollow) was not built')
  end)

  it('whose shape\'s constructor put it in a collider or a space is an error', function()
    local Held = S.hapes.ConvexPolygon:extend()
    function Held:new(x, y)
      triangle(self, x, y)
      self.holder = S.trikers.Collider(self)
    end
    S.hapes.SpecHeld = Held
    raisesAt(function() local _ = S.trikers.SpecHeld(0, 0) end, 'argument 1 already belongs to a collider')
    local space = S.pace()
    local Spaced = S.hapes.ConvexPolygon:extend()
    function Spaced:new(x, y)
      triangle(self, x, y)
      space:add(self)
    end
    S.hapes.SpecSpaced = Spaced
    raisesAt(function() local _ = S.trikers.SpecSpaced(0, 0) end, 'argument 1 is in a space')
    -- (a space's fields set by the game, one without the other: an error naming the field)
    local Sid = S.hapes.ConvexPolygon:extend()
    function Sid:new(x, y)
      triangle(self, x, y)
      self._sid = 3
    end
    S.hapes.SpecSid = Sid
    raisesAt(function() local _ = S.trikers.SpecSid(0, 0) end, "argument 1's field _sid was changed (now 3)")
    local Where = S.hapes.ConvexPolygon:extend()
    function Where:new(x, y)
      triangle(self, x, y)
      self._space = {}
    end
    S.hapes.SpecWhere = Where
    raisesAt(function() local _ = S.trikers.SpecWhere(0, 0) end, "argument 1's field _space was changed (now table)")
  end)

  it('whose class makes something that is not a shape is an error', function()
    local Base = S.hapes.ConvexPolygon:extend()
    local Odd = Base:extend()
    getmetatable(Odd).__call = function() return 'nope' end -- (Base's: how Odd(...) is made)
    S.hapes.SpecOdd = Odd
    raisesAt(function() local _ = S.trikers.SpecOdd(0, 0) end, 'a strike shape or collider, got string "nope"')
    local Odder = Base:extend()
    getmetatable(Odder).__call = function() return { _pose = 1 } end -- (a table, with a pose, of no class)
    S.hapes.SpecOdder = Odder
    raisesAt(function() local _ = S.trikers.SpecOdder(0, 0) end, 'a strike shape or collider, got table')
  end)

  it('of a subclass with an add of its own gets its shape through that add', function()
    local Counted = S.trikers.Circle:extend()
    function Counted:add(...)
      self.adds = (self.adds or 0) + 1
      return Counted.super.add(self, ...)
    end
    local c = Counted(0, 0, 1)
    assert.equals(1, c.adds)
    assert.equals(1, c:getShapeCount())
  end)

  it('holds its shape as Collider.new would have made it', function()
    local c = S.trikers.Rectangle(3, 4, 10, 6, 0.5)
    local s = c:unpack()
    assert.equals(c, s:getParent())
    assert.equals(s, c._shapes[1])
    assert.equals(c, c._shapes[0])
    assert.is_nil(c._shapes[2])
    assert.same({ -1, false, false, false }, { c._nleaves, c._massOK, c._clean, c._single })
    -- (the cache slots as a collider of the same shape has them, but the angle, which a
    -- single-shape collider takes from its shape)
    local ref = S.trikers.Collider(S.hapes.Rectangle(3, 4, 10, 6, 0.5))
    for k = 1, layout.CSIZE do
      if k ~= layout.CANGLE then assert.equals(ref[k], c[k], 'slot ' .. k) end
    end
    assert.equals(0.5, c[layout.CANGLE])
    nearList({ c:getBbox() }, { ref:getBbox() }, 0)
    near(c:getAngle(), 0.5, 0)
  end)
end)

describe('a shape file dropped into strike/shapes/', function()
  local path = 'strike/shapes/SpecDroppedKite.lua'
  local source = [[
local ConvexPolygon = require((...):match('^(.-)[^%.]+$') .. 'ConvexPolygon')
local Kite = ConvexPolygon:extend()
function Kite:new(x, y, w, h)
  self.w, self.h = w, h
  Kite.super.new(self, x, y - h / 4, x + w / 2, y, x, y + 3 * h / 4, x - w / 2, y)
end
function Kite:unpack()
  local x, y = self:getCentroid()
  return x, y, self.w, self.h
end
return Kite
]]

  it('is found by name, as a shape and as a single-shape collider', function()
    local f = assert(io.open(path, 'w'))
    f:write(source)
    f:close()
    finally(function() os.remove(path) end)
    local Kite = S.hapes.SpecDroppedKite
    assert.is_table(Kite)
    assert.equals('SpecDroppedKite', Kite.name)
    near(Kite(0, 0, 2, 4):getArea(), 4)
    local c = S.trikers.SpecDroppedKite(0, 0, 2, 4)
    assert.equals(Kite, getmetatable((c:unpack())))
  end)
end)

describe('a user-defined collider', function()
  -- The Capsule walkthrough, line for line.
  local Circle, Rectangle = S.hapes.Circle, S.hapes.Rectangle
  local Pill = S.trikers.Collider:extend()
  function Pill:new(x, y, dx, dy, angle_rads)
    self.shapes = {}
    self.centroid = { x = 0, y = 0 }
    self.radius = 0
    self.angle = angle_rads or 0
    local hx, hy = dx / 2, dy / 2
    self:add(
      Circle(x, y - hy, hx),
      Circle(x, y + hy, hx),
      Rectangle(x, y, dx, dy)
    )
    self:calcAreaCentroid()
    self:calcRadius()
    self:rotate(self.angle)
  end

  it('works with the walkthrough as written', function()
    local p = Pill(0, 0, 10, 20, pi / 2)
    nearList({ p:getBbox() }, { -15, -5, 30, 10 })
    near(p:getAngle(), pi / 2)
    p:rotateTo(0)
    nearList({ p:getBbox() }, { -5, -15, 10, 30 })
    nearList({ p:getCentroid() }, { 0, 0 })
    near(p:getRadius(), 15)
  end)

  it('registers by assignment and copies as its own class', function()
    S.trikers.Pill = Pill
    assert.equals(Pill, S.trikers.Pill)
    local p = S.trikers.Pill(0, 0, 10, 20):copy(5, 5)
    assert.is_true(p:is(Pill))
    nearList({ p:getCentroid() }, { 5, 5 })
    assert.truthy(S.triking(p, S.trikers.Circle(5, 5, 1)))
  end)
end)

describe('a collider whose constructor only adds (no Collider.new)', function()
  local Twin = S.trikers.Collider:extend()
  function Twin:new(x, y) self:add(S.hapes.Circle(x, y, 5), S.hapes.Rectangle(x, y + 5, 10, 10)) end

  it('collides at once, before any other query', function()
    local m = S.triking(Twin(0, 0), S.trikers.Circle(3, 0, 2))
    assert.truthy(m)
    near(m.depth, 4)
    assert.truthy(S.triking(S.trikers.Circle(3, 0, 2), Twin(0, 0)))
    assert.is_true(S.aabb(Twin(0, 0), S.trikers.Circle(3, 0, 2)))
  end)
end)

describe('a collider file dropped into strike/colliders/', function()
  local path = 'strike/colliders/SpecDroppedPair.lua'
  local source = [[
local root = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(root .. '.colliders.Collider')
local Circle = require(root .. '.shapes.Circle')
local Pair = Collider:extend()
function Pair:new(x, y, gap, r)
  Collider.new(self, Circle(x - gap / 2, y, r), Circle(x + gap / 2, y, r))
end
return Pair
]]

  it('is found by name', function()
    local f = assert(io.open(path, 'w'))
    f:write(source)
    f:close()
    finally(function() os.remove(path) end)
    local c = S.trikers.SpecDroppedPair(0, 0, 10, 2)
    assert.is_true(c:is(S.trikers.Collider))
    assert.equals('SpecDroppedPair', S.trikers.SpecDroppedPair.name)
    nearList({ c:getBbox() }, { -7, -2, 14, 4 })
  end)
end)
