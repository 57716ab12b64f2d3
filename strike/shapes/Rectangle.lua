--- A rectangle centred on a point, rotatable.
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local ConvexPolygon = require(ROOT .. '.shapes.ConvexPolygon')
local VertexShape = require(ROOT .. '.base.VertexShape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local ANGLE, ROUND, SCALE = layout.ANGLE, layout.ROUND, layout.SCALE
local badSelf, type = check.badSelf, type

local safeConvex = ConvexPolygon._safeConvex
local xs, ys = {}, {} -- (the corners, for the constructor: never kept)

---@class strike.Rectangle : strike.ConvexPolygon
local Rectangle = ConvexPolygon:extend()
Rectangle.name = 'Rectangle'

--- The empty instance `Rectangle(...)` fills: room for 4 vertices (ConvexPolygon's would
--- count the arguments as points).
---@return table
function Rectangle._alloc() return VertexShape._alloc(4) end

--- A dx-by-dy rectangle (dy defaults to dx) centred on (x, y), turned by `angle` radians.
--- Unrotated, edge 1 is the min-y side (normal (0, -1)), then +x, max-y and -x.
--- With `radius` (> 0, below half the shorter side) its corners are rounded by it: it still
--- spans dx by dy; its vertices are those of its core, the (dx - 2 radius) by
--- (dy - 2 radius) rectangle, and its kind is 'rounded'.
---@param x number
---@param y number
---@param dx number
---@param dy number|nil
---@param angle number|nil
---@param radius number|nil
function Rectangle:new(x, y, dx, dy, angle, radius)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Rectangle:new') end
  check.number(x, 'strike.Rectangle', 'x')
  check.number(y, 'strike.Rectangle', 'y')
  check.positive(dx, 'strike.Rectangle', 'width')
  if dy == nil then dy = dx end
  check.positive(dy, 'strike.Rectangle', 'height')
  angle = check.optNumber(angle, 'strike.Rectangle', 'angle', 0)
  local hx, hy = dx / 2, dy / 2
  if x - hx == x + hx or y - hy == y + hy then
    -- (its corners round to the same coordinates there: a size below the spacing of doubles
    -- at that position, not a degenerate outline)
    check.fail(('strike.Rectangle: a %s by %s rectangle cannot be told from a point at (%s, %s): its corners round'
      .. ' to the same coordinates, doubles there being about %s apart; move it nearer the origin or make it'
      .. ' larger'):format(check.describe(dx), check.describe(dy), check.describe(x), check.describe(y),
      ('%.2g'):format(math.max(math.abs(x), math.abs(y)) * 2 ^ -52)))
  end
  if radius ~= nil then
    ConvexPolygon._checkRounding('strike.Rectangle', radius)
    if not (radius < hx and radius < hy) then
      check.fail(('strike.Rectangle: radius must be below half the shorter side (%s), got %s; a capsule is'
        .. ' S.hapes.Capsule, a disc S.hapes.Circle'):format(check.describe(math.min(hx, hy)),
        check.describe(radius)))
    end
    local cx, cy = hx - radius, hy - radius
    VertexShape._sizesNext(dx, dy) -- (its width and height: unpack's)
    Rectangle.super.new(self, { x - cx, y - cy, x + cx, y - cy, x + cx, y + cy, x - cx, y + cy, radius = radius })
  elseif safeConvex(x, y, 4, hx < hy and dx or dy, hx + hy) then
    -- (four corners in positive winding: the hull would return them as they are)
    xs[1], xs[2], xs[3], xs[4] = x - hx + 0.0, x + hx + 0.0, x + hx + 0.0, x - hx + 0.0
    ys[1], ys[2], ys[3], ys[4] = y - hy + 0.0, y - hy + 0.0, y + hy + 0.0, y + hy + 0.0
    self:_fromConvex(xs, ys, 4, 'strike.Rectangle', dx, dy)
  else
    VertexShape._sizesNext(dx, dy)
    Rectangle.super.new(self, x - hx, y - hy, x + hx, y - hy, x + hx, y + hy, x - hx, y + hy)
  end
  self:_placeCentroid(x, y) -- the exact centre, free of round-off
  if angle ~= 0 then self:rotate(angle) end
end

--- Arguments that rebuild the rectangle as it is now: x, y, width, height, angle, and the
--- corner radius when it is rounded.
---@return number, number, number, number, number, number|nil
function Rectangle:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  local s = self[SCALE]
  local x, y = self:getCentroid()
  local w, h = self:_sizes()
  if self[ROUND] > 0 then return x, y, w * s, h * s, self[ANGLE], self[ROUND] * s end
  return x, y, w * s, h * s, self[ANGLE]
end

return Rectangle
