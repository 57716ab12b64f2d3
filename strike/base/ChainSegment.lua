--- One segment of a chain (S.trikers.Chain): a one-sided Edge that knows its neighbours.
---
--- Geometry is an Edge's (vertices p1, p2; face 1 is p1 to p2 with the normal
--- n = (ey, -ex) / len, face 2 is p2 to p1), plus two *ghost vertices*: the chain's point
--- before p1 and the one after p2 (none at an open chain's ends). They are stored like the
--- vertices, in the local frame (relative to the centroid, unrotated, unscaled), so they
--- follow every transform of the segment or of its collider.
---
--- Solid side: face 1's normal n points to the FREE side. For a loop given in positive
--- winding (counter-clockwise with y up, clockwise on a LÖVE screen), n points outward;
--- for an open chain the free side is on the right of the direction of travel with y up
--- (on the left with y down: a floor given from left to right on a LÖVE screen has its
--- free side above it). Shapes whose centroid is behind the segment's line never collide
--- with it.
---
--- Corners: the corner at p1 is convex when the chain turns there so that the free side
--- gets wider: cross(p1 - prev, p2 - p1) > 0 (a left turn with y up); likewise at p2. An
--- open end counts as convex, like the end of a lone edge. The narrow phase
--- (strike/collide/chain.lua) reads these, in slots after the vertex records (layout.lua),
--- refreshed with the world vertices:
---   vertex 1 and 2      p1 and p2, and face 1's normal n, the segment's own (VertexShape's
---                       records, see strike/base/layout.lua)
---   G1X, G1Y            at p1: the previous segment's unit normal, or at an open start
---                       the outward tangent -(p2 - p1) / len
---   G2X, G2Y            at p2: the next segment's unit normal, or at an open end the
---                       outward tangent (p2 - p1) / len
---   CONVEX1, CONVEX2    whether the corner at p1 (p2) is convex (true at an open end)
---   HASPREV, HASNEXT    whether there is a neighbour there
--- The ghost vertices are kept local (LPREVX ... LNEXTY) and put in world coordinates when
--- asked for (getGhostVertices): nothing else reads them.
local ROOT = (...):match('^(.-)%.base%.[^%.]+$')
local Edge = require(ROOT .. '.shapes.Edge')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local CONVEX1, CONVEX2, G1X, G1Y = layout.CONVEX1, layout.CONVEX2, layout.G1X, layout.G1Y
local G2X, G2Y, HASNEXT, HASPREV = layout.G2X, layout.G2Y, layout.HASNEXT, layout.HASPREV
local LG1X, LG1Y, LG2X, LG2Y = layout.LG1X, layout.LG1Y, layout.LG2X, layout.LG2Y
local LNEXTX, LNEXTY, LPREVX, LPREVY = layout.LNEXTX, layout.LNEXTY, layout.LPREVX, layout.LPREVY
local COS, SCALE, SIN = layout.COS, layout.SCALE, layout.SIN
local rotate = require(ROOT .. '.vec').rotate

local X, Y = layout.X, layout.Y
local number, fail, describe = check.number, check.fail, check.describe
local badSelf, type = check.badSelf, type
local unit, checkLength = require(ROOT .. '.limits').unit, Edge._checkLength

---@class strike.ChainSegment : strike.Edge
local ChainSegment = Edge:extend()
ChainSegment.name = 'ChainSegment'
ChainSegment.kind = 'chain'

local FNAME = 'strike.ChainSegment'

--- The empty instance (class.lua): an edge's slots and a segment's own (layout.lua), and room
--- for the named fields every shape has.
---@return table
function ChainSegment._alloc() return Edge._allocSlots(layout.CHAIN_SIZE) end

-- An optional ghost vertex: both coordinates, or neither.
local function optGhost(x, y, what)
  if x == nil and y == nil then return false end
  number(x, FNAME, what .. ' x')
  number(y, FNAME, what .. ' y')
  return true
end

--- A one-sided segment from (x1, y1) to (x2, y2) with the ghost vertices (x0, y0), the
--- chain's point before p1, and (x3, y3), the point after p2; either pair may be nil (an
--- open end). S.trikers.Chain builds these; the endpoints must differ, and each ghost
--- vertex must differ from the endpoint it joins.
---@param x1 number
---@param y1 number
---@param x2 number
---@param y2 number
---@param x0 number|nil
---@param y0 number|nil
---@param x3 number|nil
---@param y3 number|nil
function ChainSegment:new(x1, y1, x2, y2, x0, y0, x3, y3)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.ChainSegment:new') end
  number(x1, FNAME, 'x1')
  number(y1, FNAME, 'y1')
  number(x2, FNAME, 'x2')
  number(y2, FNAME, 'y2')
  if x1 == x2 and y1 == y2 then
    fail(('%s: the endpoints must differ, got (%s, %s) twice'):format(FNAME, describe(x1), describe(y1)))
  end
  local hasPrev, hasNext = optGhost(x0, y0, 'previous point'), optGhost(x3, y3, 'next point')
  if hasPrev and x0 == x1 and y0 == y1 then fail(FNAME .. ': the previous point must differ from p1') end
  if hasNext and x3 == x2 and y3 == y2 then fail(FNAME .. ': the next point must differ from p2') end
  x1, y1, x2, y2 = x1 + 0.0, y1 + 0.0, x2 + 0.0, y2 + 0.0 -- (floats: integer arithmetic wraps on Lua 5.3+)
  if hasPrev then x0, y0 = x0 + 0.0, y0 + 0.0 end
  if hasNext then x3, y3 = x3 + 0.0, y3 + 0.0 end
  -- (the neighbouring segments must be segments strike accepts too: strike/limits.lua)
  checkLength(FNAME, x1, y1, x2, y2)
  if hasPrev then checkLength(FNAME, x0, y0, x1, y1, 'previous segment (previous point to p1)') end
  if hasNext then checkLength(FNAME, x2, y2, x3, y3, 'next segment (p2 to the next point)') end
  Edge.new(self, x1, y1, x2, y2)
  for k = layout.HASPREV, layout.CHAIN_SIZE do self[k] = 0 end -- (no holes: an absent ghost is 0)
  local cx, cy = self:getCentroid()
  local ex, ey = unit(x2 - x1, y2 - y1)
  self[HASPREV], self[HASNEXT] = hasPrev, hasNext
  if hasPrev then
    local dx, dy = unit(x1 - x0, y1 - y0)
    self[LPREVX], self[LPREVY] = x0 - cx, y0 - cy
    self[LG1X], self[LG1Y] = dy, -dx
    self[CONVEX1] = dx * ey - dy * ex > 0
  else
    self[LG1X], self[LG1Y] = -ex, -ey
    self[CONVEX1] = true
  end
  if hasNext then
    local dx, dy = unit(x3 - x2, y3 - y2)
    self[LNEXTX], self[LNEXTY] = x3 - cx, y3 - cy
    self[LG2X], self[LG2Y] = dy, -dx
    self[CONVEX2] = ex * dy - ey * dx > 0
  else
    self[LG2X], self[LG2Y] = ex, ey
    self[CONVEX2] = true
  end
end

--- Recompute the world vertices, normals and bounds (VertexShape's refresh), then the
--- corner normals.
function ChainSegment:_refresh()
  Edge._refresh(self)
  local c, s = self[COS], self[SIN]
  self[G1X], self[G1Y] = rotate(self[LG1X], self[LG1Y], c, s)
  self[G2X], self[G2Y] = rotate(self[LG2X], self[LG2Y], c, s)
end

--- The ghost vertices in world coordinates: the chain's point before p1 and the one after
--- p2, each nil, nil at an open chain's end.
---@return number|nil x0, number|nil y0, number|nil x3, number|nil y3
function ChainSegment:getGhostVertices()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.ChainSegment:getGhostVertices') end
  local k = self[SCALE]
  local sc, ss = self[COS] * k, self[SIN] * k
  local cx, cy = self[X], self[Y]
  local x0, y0, x3, y3
  if self[HASPREV] then
    local x, y = rotate(self[LPREVX], self[LPREVY], sc, ss)
    x0, y0 = cx + x, cy + y
  end
  if self[HASNEXT] then
    local x, y = rotate(self[LNEXTX], self[LNEXTY], sc, ss)
    x3, y3 = cx + x, cy + y
  end
  return x0, y0, x3, y3
end

--- Whether the chain's corner at vertex i (1: p1, 2: p2) is convex: the free side gets
--- wider there (an open end counts as convex). Nil for any other i.
---@param i integer
---@return boolean|nil
function ChainSegment:isConvex(i)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.ChainSegment:isConvex') end
  if i == 1 then return self[CONVEX1] elseif i == 2 then return self[CONVEX2] end
  return nil
end

--- Arguments that rebuild the segment as it is now: x1, y1, x2, y2, x0, y0, x3, y3 (the
--- ghost vertices nil at an open end).
---@return number, number, number, number, number|nil, number|nil, number|nil, number|nil
function ChainSegment:unpack()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:unpack') end
  local x1, y1, x2, y2 = Edge.unpack(self)
  local x0, y0, x3, y3 = self:getGhostVertices()
  return x1, y1, x2, y2, x0, y0, x3, y3
end

return ChainSegment
