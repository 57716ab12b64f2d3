-- The custom-collider walkthrough: a capsule made from two Circles and a Rectangle in a
-- collider class of the game's own (Collider:extend()), as the original Strike's README
-- builds it ("Let's make a Capsule!"), in strike's conventions: the height includes the
-- caps, the angle is turned once, and a bad height is refused at the caller's line. The
-- class is written here as the README shows it, and played with as a game would.
-- (It is not S.trikers.Capsule, strike's own capsule.)
local S = require('strike')
local expect = require('spec.helpers.expect')
local near, nearList, raisesAt = expect.near, expect.nearList, expect.raisesAt
local pi = math.pi

-- The walkthrough's code ------------------------------------------------------------------
local Collider, Circle, Rectangle = S.trikers.Collider, S.hapes.Circle, S.hapes.Rectangle

local Capsule = Collider:extend()

-- A capsule centred on (x, y), w wide and h tall caps included (h >= w: the caps have
-- radius w / 2), turned by angle. Unturned, the caps are on the vertical axis. Members:
-- the two caps (the -y one first), then the rectangle between their centres.
function Capsule:new(x, y, w, h, angle)
  if type(w) ~= 'number' or type(h) ~= 'number' or h < w then
    -- (level 3: the line that called Capsule(...), past Capsule:new and the class's call)
    error(('Capsule: height (caps included) must be a number >= the width, got width %s and height %s')
      :format(tostring(w), tostring(h)), 3)
  end
  local r, straight = w / 2, h - w
  if straight > 0 then
    Capsule.super.new(self,
      Circle(x, y - straight / 2, r),
      Circle(x, y + straight / 2, r),
      Rectangle(x, y, w, straight))
  else
    Capsule.super.new(self, Circle(x, y, r)) -- as tall as it is wide: a circle
  end
  self:rotate(angle or 0)
end
-- -------------------------------------------------------------------------------------------

local function bbox(c) return { c:getBbox() } end
local function centre(s) return { s:getCentroid() } end

describe('the custom-collider walkthrough: a Capsule from two circles and a rectangle', function()
  it('builds its members: two caps of radius w / 2 and the rectangle between them', function()
    local c = Capsule(0, 0, 10, 30)
    assert.is_true(c:is(Collider) and c:is(Capsule))
    assert.is_false(c:is(S.trikers.Capsule))
    assert.equals(3, c:getShapeCount())
    local top, bottom, mid = (c:unpack()), select(2, c:unpack()), select(3, c:unpack())
    assert.is_true(top:is(Circle) and bottom:is(Circle) and mid:is(Rectangle))
    assert.equals(c, top:getParent())
    near(top:getRadius(), 5)
    near(bottom:getRadius(), 5)
    nearList(centre(top), { 0, -10 })
    nearList(centre(bottom), { 0, 10 })
    nearList(bbox(mid), { -5, -10, 10, 20 })
    nearList(bbox(c), { -5, -15, 10, 30 }) -- 30 tall, caps included
    nearList({ c:getCentroid() }, { 0, 0 })
    near(c:getRadius(), 15)
    near(c:getAngle(), 0)
    -- as tall as it is wide: one circle
    local round = Capsule(3, 4, 10, 10)
    assert.equals(1, round:getShapeCount())
    assert.is_true((round:unpack()):is(Circle))
    nearList(bbox(round), { -2, -1, 10, 10 })
  end)

  it('has the area of its members: the caps overlap the rectangle, so the sum counts their inner halves twice',
    function()
    local c = Capsule(2, 3, 10, 30)
    near((c:unpack()):getArea(), 25 * pi)
    near(select(2, c:unpack()):getArea(), 25 * pi)
    near(select(3, c:unpack()):getArea(), 10 * 20)
    near(c:getArea(), 200 + 50 * pi) -- (the capsule itself covers 200 + 25 pi)
    local area, x, y = c:getAreaCentroid()
    nearList({ area, x, y }, { 200 + 50 * pi, 2, 3 })
    c:scale(2)
    near(c:getArea(), 4 * (200 + 50 * pi))
    nearList(bbox(c), { -8, -27, 20, 60 })
  end)

  it('collides with a box through whichever member it reaches; the round caps miss its bounding box\'s corners',
    function()
    local c = Capsule(0, 0, 10, 30)
    local box = Rectangle(0, -15 - 2 + 1, 4, 4) -- 1 px into the top cap
    local m = S.triking(c, box)
    assert.truthy(m)
    nearList({ m.x, m.y, m.nx, m.ny, m.depth }, { 0, -1, 0, -1, 1 })
    assert.equals((c:unpack()), m.colliderShape)
    box:translate(m.x, m.y)
    assert.is_false(S.triking(c, box)) -- touching is not colliding

    box = Rectangle(5 + 2 - 1, 0, 4, 4) -- 1 px into the straight side
    m = S.triking(c, box)
    nearList({ m.x, m.y, m.depth }, { 1, 0, 1 })
    assert.equals(select(3, c:unpack()), m.colliderShape)
    m = S.triking(box, c) -- the other order: the opposite vector
    nearList({ m.x, m.y, m.depth }, { -1, 0, 1 })

    -- in the corner of the bounding box, outside the cap (4, -14 is 5.66 from its centre)
    box = Rectangle(5, -15, 2, 2)
    assert.is_true(S.aabb(c, box))
    assert.is_false(S.triking(c, box))
    assert.is_false(S.triking(box, c))
  end)

  it('turns about its centre, members and all, and collides where it lies', function()
    local c = Capsule(0, 0, 10, 30, pi / 2) -- lying down
    near(c:getAngle(), pi / 2)
    nearList(bbox(c), { -15, -5, 30, 10 })
    nearList(centre((c:unpack())), { 10, 0 }) -- the -y cap turned to +x (y grows downward)
    nearList(centre(select(2, c:unpack())), { -10, 0 })
    nearList(bbox(select(3, c:unpack())), { -10, -5, 20, 10 })
    -- a box on top, 1 px in: in the middle, and where a cap meets the rectangle
    for _, x in ipairs({ 0, 10 }) do
      local m = S.triking(c, Rectangle(x, -5 - 2 + 1, 4, 4))
      nearList({ m.x, m.y, m.depth }, { 0, -1, 1 })
    end
    c:rotateTo(0)
    nearList(bbox(c), { -5, -15, 10, 30 })
    nearList(centre((c:unpack())), { 0, -10 })
    c:rotate(pi / 2, 0, 15) -- about its bottom end: it lies to the right of it
    nearList(bbox(c), { 0, 10, 30, 10 })
    nearList(centre((c:unpack())), { 25, 15 })
  end)

  it('copies as its own class, moved and turned', function()
    local c = Capsule(0, 0, 10, 30):copy(5, 5, pi / 2)
    assert.is_true(c:is(Capsule))
    assert.equals(3, c:getShapeCount())
    nearList({ c:getCentroid() }, { 5, 5 })
    nearList(bbox(c), { -10, 0, 30, 10 })
    assert.truthy(S.triking(c, S.trikers.Circle(5, 5, 1)))
  end)

  it('refuses a height below the width at the caller\'s line; its members check the rest', function()
    raisesAt(function() Capsule(0, 0, 10, 5) end,
      'Capsule: height (caps included) must be a number >= the width, got width 10 and height 5')
    raisesAt(function() Capsule(0, 0, 10) end, 'got width 10 and height nil')
    raisesAt(function() Capsule(0, 0, nil, 10) end, 'got width nil and height 10')
    -- a negative width passes the walkthrough's one check: its caps refuse it, naming strike.Circle
    local ok, err = pcall(Capsule, 0, 0, -4, 10)
    assert.is_false(ok)
    assert.truthy(tostring(err):find('strike.Circle: radius must be a finite number > 0, got -2', 1, true))
  end)
end)
