--- A chain: a Collider of one-sided segments joined end to end, with ghost vertices so
--- that bodies slide across the joints without catching on them (Box2D's chain shape;
--- see strike/base/ChainSegment.lua for the sides and corners, strike/collide/chain.lua
--- for the narrow phase).
---
--- Free side: each segment's face-1 normal (ey, -ex) / len points to the free side. For a
--- loop given in positive winding (counter-clockwise with y up, clockwise on a LÖVE
--- screen) that is outward; for an open chain it is the right of the direction of travel
--- with y up, which on a LÖVE screen (y down) is the left: a floor given from left to
--- right is solid below and free above. Bodies whose centroid is behind a segment pass
--- through it. The chain should not cross itself (this is not checked).
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(ROOT .. '.colliders.Collider')
local ChainSegment = require(ROOT .. '.base.ChainSegment')
local check = require(ROOT .. '.check')
local unpack = require(ROOT .. '.compat').unpack

local badSelf, badCollider, type = check.badSelf, check.badCollider, type
local fail, describe = check.fail, check.describe
local checkLength = require(ROOT .. '.shapes.Edge')._checkLength

---@class strike.Chain : strike.Collider
local Chain = Collider:extend()
Chain.name = 'Chain'

local FNAME = 'strike.Chain'

--- A chain through the points x1, y1, x2, y2, ... (or one table {x1, y1, ...}), followed
--- by an optional boolean `loop` (default false): when true, a last segment joins the
--- last point back to the first. Its leaves are S.trikers.Chain's ChainSegments, one per
--- consecutive pair of points, in order. Consecutive duplicate points are dropped (for a
--- loop, also a last point equal to the first); at least 2 distinct points are needed, 3
--- for a loop.
---@param ... number|number[]|boolean
function Chain:new(...)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Chain:new') end
  local count, first = select('#', ...), ...
  local loop, xs, ys, n
  if type(first) == 'table' then
    if count > 2 then
      fail(('%s: expected a table of coordinates and an optional loop flag, got %d arguments'):format(FNAME, count))
    end
    loop = select(2, ...)
    local tail = first[#first]
    if #first % 2 == 1 and type(tail) ~= 'number' then
      fail(('%s: the loop flag goes after the table, as in S.trikers.Chain({x1, y1, ...}, true); got %s as the'
        .. ' last value of the table'):format(FNAME, describe(tail)))
    end
    xs, ys, n = check.coordinates(FNAME, first)
  else
    local args = { ... }
    local last = args[count]
    -- (after an odd number of values, anything but a number is meant as the flag)
    if count > 0 and (type(last) == 'boolean' or (count % 2 == 1 and type(last) ~= 'number')) then
      loop, count = last, count - 1
    end
    xs, ys, n = check.coordinates(FNAME, unpack(args, 1, count))
  end
  if loop ~= nil and type(loop) ~= 'boolean' then
    fail(('%s: loop must be a boolean, got %s'):format(FNAME, describe(loop)))
  end
  loop = loop == true
  -- drop consecutive duplicates (cyclically for a loop)
  local px, py, m = {}, {}, 0
  for i = 1, n do
    if m == 0 or xs[i] ~= px[m] or ys[i] ~= py[m] then
      m = m + 1
      px[m], py[m] = xs[i], ys[i]
    end
  end
  if loop and m > 1 and px[m] == px[1] and py[m] == py[1] then m = m - 1 end
  local need = loop and 3 or 2
  if m < need then
    fail(('%s: %s needs at least %d distinct points, got %d'):format(FNAME, loop and 'a loop' or 'a chain', need, m))
  end
  for i = 1, loop and m or m - 1 do -- (each segment's length within strike's limits: limits.lua)
    local j = i < m and i + 1 or 1
    checkLength(FNAME, px[i], py[i], px[j], py[j], i)
  end
  local segments = {}
  for i = 1, loop and m or m - 1 do
    local j = i < m and i + 1 or 1
    local h, k -- the ghost vertices' indices, nil at an open end
    if i > 1 then h = i - 1 elseif loop then h = m end
    if j < m then k = j + 1 elseif loop then k = 1 end
    segments[i] = ChainSegment(px[i], py[i], px[j], py[j], h and px[h], h and py[h], k and px[k], k and py[k])
  end
  Collider._take(self, segments) -- (Collider.new(self, ...) without the checks: they are new)
  self._loop = loop
end

--- Whether the chain is closed (its last point joined back to the first).
---@return boolean
function Chain:isLoop()
  if type(self) ~= 'table' or self._shapes == nil then badCollider(self, 'strike.Chain:isLoop') end
  return self._loop
end

return Chain
