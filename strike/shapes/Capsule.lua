--- A capsule (stadium): a segment, its core, swept by a circle; one convex shape of the
--- 'rounded' kind (collide/rounded.lua), exact everywhere: no seams between caps and body.
--- Its vertices are the core segment's two ends (equal when the capsule is a disc), its
--- rounding radius the caps' radius.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local ANGLE, HALF, ROUND, SCALE, SHORT = layout.ANGLE, layout.HALF, layout.ROUND, layout.SCALE, layout.SHORT
local limits = require(ROOT .. '.limits')

local pi = math.pi
local badSelf, type = check.badSelf, type
local MIN_LENGTH, MAX_LENGTH = limits.MIN_LENGTH, limits.MAX_LENGTH
-- A disc's local geometry, for the constructor (its vertices set each time): never kept.
local disc = { 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0, 0.0 }

---@class strike.Capsule : strike.VertexShape
local Capsule = VertexShape:extend()
Capsule.name = 'Capsule'
Capsule._alloc = VertexShape._alloc2
Capsule._shortName = 'shortest length (the caps\' radius, or the straight part)'

-- Raise an error at the caller's line: `what` (value v) is out of strike's limits on
-- lengths (strike/limits.lua), below (`least`) or above `bound`.
local function refuse(what, v, bound, least)
  check.fail(('strike.Capsule: %s too %s: got %s, %s %s (strike accepts lengths from %s to %s)'):format(what,
    least and 'small' or 'large', check.describe(v), least and 'below' or 'above', check.describe(bound),
    check.describe(MIN_LENGTH), check.describe(MAX_LENGTH)))
end

--- A capsule centred on (x, y), `w` wide and `h` tall **including** both caps (h >= w; the
--- caps have radius w / 2), turned by `angle` (default 0). Unrotated, the caps sit on the
--- vertical axis: the core runs from (x, y - (h - w) / 2) to (x, y + (h - w) / 2), vertex 1
--- first. h == w gives a disc (a core of length 0).
---@param x number
---@param y number
---@param w number
---@param h number
---@param angle number|nil
function Capsule:new(x, y, w, h, angle)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Capsule:new') end
  check.number(x, 'strike.Capsule', 'x')
  check.number(y, 'strike.Capsule', 'y')
  check.positive(w, 'strike.Capsule', 'width')
  check.positive(h, 'strike.Capsule', 'height')
  angle = check.optNumber(angle, 'strike.Capsule', 'angle', 0)
  if h < w then
    check.fail(('strike.Capsule: height (caps included) must be at least the width, got width %s and height %s')
      :format(w, h))
  end
  local r, len = w / 2, h - w
  if r < MIN_LENGTH then refuse('width (twice the caps\' radius)', w, 2 * MIN_LENGTH, true) end
  if not (h / 2 <= MAX_LENGTH) then -- luacheck: ignore 581 (NaN is too large)
    refuse('size (half the height: from the centre to the farthest point)', h / 2, MAX_LENGTH, false)
  end
  if len > 0 and len < MIN_LENGTH then refuse('straight part (height - width, when not 0)', len, MIN_LENGTH, true) end
  x, y, r, len = x + 0.0, y + 0.0, r + 0.0, len + 0.0 -- (floats: integer products wrap on Lua 5.3+)
  local half = len / 2
  self:_setVertices({ x, x }, { y - half, y + half }, 2, x, y, pi * r * r + 2 * r * len)
  if len == 0 then
    -- a disc: the core's two faces keep the normals a straight part would have (+x, -x)
    -- (the local geometry is shared, never changed: see VertexShape.lua)
    local l = self._l
    disc[1], disc[2], disc[5], disc[6] = l[1], l[2], l[5], l[6]
    self._l = VertexShape._shareGeometry(disc, 2)
  end
  self[HALF] = 1
  self[SHORT] = len > 0 and (len < r and len or r) or r
  self:_setRounding(r)
  self:_placeCentroid(x, y) -- (the exact centre)
  self:_checkNew('strike.Capsule')
  if angle ~= 0 then self:rotate(angle) end
end

--- Width and height (caps included), as they are now.
---@return number width, number height
function Capsule:getDimensions()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Capsule:getDimensions') end
  local s = self[SCALE]
  local r = self[ROUND] * s
  local l = self._l
  return 2 * r, 2 * r + 2 * (l[2] < 0 and -l[2] or l[2]) * s
end

--- Arguments that rebuild the capsule as it is now: x, y, width, height, angle.
---@return number, number, number, number, number
function Capsule:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  local w, h = self:getDimensions()
  local x, y = self:getCentroid()
  return x, y, w, h, self[ANGLE]
end

return Capsule
