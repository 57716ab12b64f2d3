--- A true circle: a point (its position, the centroid) with a radius. Its world data is
--- the header every shape has (strike/base/layout.lua): bounds, centre and world radius,
--- which the narrow phase reads; its local geometry is its radius, unscaled (the slot RADIUS).
local ROOT = (...):match('^(.-)%.shapes%.[^%.]+$')
local Shape = require(ROOT .. '.base.Shape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local ANGLE, AREA, COUNT, DIRTY = layout.ANGLE, layout.AREA, layout.COUNT, layout.DIRTY
local RADIUS, SCALE, SHORT = layout.RADIUS, layout.SCALE, layout.SHORT
local limits = require(ROOT .. '.limits')

local X, Y, R = layout.X, layout.Y, layout.R
local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY

local sqrt, pi = math.sqrt, math.pi
local number, positive = check.number, check.positive
local badSelf, type = check.badSelf, type
local MIN_LENGTH, MAX_LENGTH = limits.MIN_LENGTH, limits.MAX_LENGTH

---@class strike.Circle : strike.Shape
local Circle = Shape:extend()
Circle.kind = 'circle'
Circle.name = 'Circle'
Circle._shortName = 'radius'

--- A circle centred on (x, y) with radius r (from 1e-100 to 1e100: strike/limits.lua), turned
--- by `angle` (default 0; the angle only matters to getAngle and to drawing).
---@param x number
---@param y number
---@param r number
---@param angle number|nil
function Circle:new(x, y, r, angle)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Circle:new') end
  number(x, 'strike.Circle', 'x')
  number(y, 'strike.Circle', 'y')
  positive(r, 'strike.Circle', 'radius')
  angle = check.optNumber(angle, 'strike.Circle', 'angle', 0)
  -- (the test Shape:_checkNew makes, in the circle's words: see strike/limits.lua)
  if r > MAX_LENGTH then
    check.fail(('strike.Circle: radius too large: got %s, above %s, the largest length strike accepts'):format(
      check.describe(r), check.describe(MAX_LENGTH)))
  end
  if r < MIN_LENGTH then
    check.fail(('strike.Circle: radius too small: got %s, below %s, the smallest length strike accepts (its square'
      .. ' must stay a normal double)'):format(check.describe(r), check.describe(MIN_LENGTH)))
  end
  r = r + 0.0 -- (a float: r * r must not be integer arithmetic, which wraps on Lua 5.3+)
  self[AREA] = pi * r * r
  self[RADIUS], self[SHORT] = r, r
  self:_setPose(x, y)
  self:_checkNew('strike.Circle')
  if angle ~= 0 then self:rotate(angle) end
end

function Circle:_refresh()
  local r = self[RADIUS] * self[SCALE]
  local x, y = self[X], self[Y]
  self[MINX], self[MINY], self[MAXX], self[MAXY] = x - r, y - r, x + r, y + r
  self[R] = r
  self[DIRTY] = false
end

--- The radius now (the constructor's radius times the scale).
---@return number
function Circle:getRadius()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getRadius') end
  return self[RADIUS] * self[SCALE]
end

--- The rounding radius: a circle is a point rounded by its radius (the same as getRadius).
---@return number
function Circle:getRounding()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getRounding') end
  return self[RADIUS] * self[SCALE]
end

--- Minimum and maximum of the projection on the unit vector (nx, ny).
---@param nx number
---@param ny number
---@return number min, number max
function Circle:project(nx, ny)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:project') end
  number(nx, 'strike.Shape:project', 'nx')
  number(ny, 'strike.Shape:project', 'ny')
  local d = self[X] * nx + self[Y] * ny
  local r = self[RADIUS] * self[SCALE]
  return d - r, d + r
end

--- True when the point is strictly inside (not on the circle itself). Takes x, y or {x=, y=}.
---@param x number|table
---@param y number|nil
---@return boolean
function Circle:containsPoint(x, y)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:containsPoint') end
  x, y = Shape._point(x, y, 'strike.Shape:containsPoint')
  local dx, dy, r = x - self[X], y - self[Y], self[RADIUS] * self[SCALE]
  return dx * dx + dy * dy < r * r
end

--- A circle has no vertices: nil.
---@return nil
function Circle:getVertex()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getVertex') end
  return nil
end

--- A circle has no edges: nil.
---@return nil
function Circle:getEdge()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getEdge') end
  return nil
end

--- A circle has no vertices: count 0.
---@return integer
function Circle:getVertexCount()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getVertexCount') end
  return 0
end

--- A circle has no vertices: `out` (or a new table) emptied, and 0.
---@param out table|nil
---@return table, integer
function Circle:getVertices(out)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getVertices') end
  out = out or {}
  if type(out) ~= 'table' or out._type ~= nil then check.badOut('strike.Shape:getVertices', out) end
  for i = #out, 1, -1 do out[i] = nil end
  return out, 0
end

--- The point on the circle farthest along (nx, ny).
---@param nx number
---@param ny number
---@return number x, number y
function Circle:getSupport(nx, ny)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getSupport') end
  local r = self[RADIUS] * self[SCALE]
  number(nx, 'strike.Shape:getSupport', 'nx')
  number(ny, 'strike.Shape:getSupport', 'ny')
  return self[X] + nx * r, self[Y] + ny * r
end

-- Direction from the circle's centre toward `other` (its nearest vertex, or its centre),
-- unit length; (0, -1) when they coincide.
local function axisToward(self, other)
  local cx, cy = self[X], self[Y]
  local tx, ty
  if other and other[COUNT] then
    if other[DIRTY] then other:_refresh() end
    local best = math.huge
    for i = 1, other[COUNT] do
      local x, y = other:getVertex(i)
      local dx, dy = x - cx, y - cy
      local d = dx * dx + dy * dy
      if d < best then best, tx, ty = d, x, y end
    end
  elseif other and other._type == 'shape' then
    tx, ty = other:getCentroid()
  end
  if not tx then return 0, -1 end
  local ux, uy = limits.direction(cx, cy, tx, ty) -- (unit however near or far: limits.lua)
  if not ux then return 0, -1 end
  return ux, uy
end

-- The `other` of ipairs and vecs: nil or a shape.
local function checkOther(other, fname)
  if other ~= nil and (type(other) ~= 'table' or other._type ~= 'shape' or other._pose == nil) then
    require(ROOT .. '.reserved').check(fname, 'other', other)
    check.fail(('%s: other must be a strike shape or nil, got %s'):format(fname, check.what(other)))
  end
end

local function circleEdgeIter(state, i)
  if i >= 1 then return nil end
  local self, other = state[1], state[2]
  local ax, ay = axisToward(self, other)
  local r = self[RADIUS] * self[SCALE]
  local px, py = self[X] + ax * r, self[Y] + ay * r
  -- the tangent at the point facing `other`, in positive winding
  return 1, px + ay * r, py - ax * r, px - ay * r, py + ax * r
end

--- Iterate over the circle's one pseudo-edge: the tangent segment (length 2r) at the point
--- facing `other` (its nearest vertex or its centre). Without `other`, the point at -y.
--- `for i, x1, y1, x2, y2 in circle:ipairs(other) do`.
---@param other strike.Shape|nil
---@return function, table, integer
function Circle:ipairs(other)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:ipairs') end
  checkOther(other, 'strike.Circle:ipairs')
  return circleEdgeIter, { self, other }, 0
end

local function circleVecIter(state, i)
  if i >= 1 then return nil end
  local ax, ay = axisToward(state[1], state[2])
  return 1, -ay, ax
end

--- Iterate over the one vector whose normal is the circle's SAT axis toward `other`:
--- `for i, dx, dy in circle:vecs(other) do`.
---@param other strike.Shape|nil
---@return function, table, integer
function Circle:vecs(other)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:vecs') end
  checkOther(other, 'strike.Circle:vecs')
  return circleVecIter, { self, other }, 0
end

--- Largest distance from (px, py) to the circle.
---@return number
function Circle:_farthest(px, py)
  local dx, dy = self[X] - px, self[Y] - py
  return sqrt(dx * dx + dy * dy) + self[RADIUS] * self[SCALE]
end

--- Arguments that rebuild the circle as it is now: x, y, radius, angle.
---@return number, number, number, number
function Circle:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  return self[X], self[Y], self[RADIUS] * self[SCALE], self[ANGLE]
end

return Circle
