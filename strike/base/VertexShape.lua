--- The base of every shape made of vertices: ConvexPolygon (and its subclasses) and Edge.
--- Geometry lives in flat number arrays with a count, n (the slot COUNT):
---   _l          local geometry, 4n numbers: vertex i's record starts at k = 4i - 3 and holds
---               the vertex relative to the centroid, unrotated and unscaled (l[k], l[k+1];
---               positive winding), and the unit outward normal of edge i, from vertex i to
---               vertex i + 1 (l[k+2], l[k+3]); then the class's own sizes, up to 3 numbers
---               (what its unpack gives back: a Rectangle's width and height, a RegularPolygon's
---               n and radius, an Ellipse's a, b and n; ConvexPolygon.new's `sizes`). Never
---               changed once built, so shapes share it: a shape built with the very numbers
---               (to the bit, the sign of zero and, on Lua 5.3+, integer or float included) of
---               one of the last few built takes that one's table, and a copy shares its
---               original's. Code that changes a shape's local geometry in place first takes a
---               copy of its own (_ownGeometry).
---   self[...]   world-space data, refreshed when dirty, in the shape's own array part: the
---               header every shape has, then one record per vertex (vertex, edge normal, edge
---               offset), laid out as strike/base/layout.lua says, with the shape's scalars
---               (pose, sizes, count). The narrow phase reads the shape's table and nothing
---               else, so that a test touches few cache lines and follows no pointers.
---   HALF        (slot) n / 2 when the polygon is centrally symmetric (normal i + n/2 is exactly
---               -normal i: rectangles, even regular polygons, edges), else 0; the narrow
---               phase then gets two faces' separations from one projection of the other shape.
---   ROUND       (slot) the rounding radius, unscaled: 0 for a sharp polygon; r > 0 for a rounded
---               shape (a capsule, a rounded rectangle or polygon), which is every point within
---               r of its polygon, the core (the vertices above are the core's). Its world
---               value is the header's slot R; a rounded shape has the kind 'rounded'
---               (collide/rounded.lua), a sharp one 'polygon'.
---   _seams      false (the usual case), or, for a piece of a compound (the convex pieces of
---               S.trikers.Concave), one entry per face i (edge i, from vertex i to vertex
---               i + 1, as getEdge and getNormal number them): false or nil when the face is
---               a surface; true when the whole face is a seam, a cut inside the compound with
---               a sibling piece on its other side; or, for a face that is partly seam, partly
---               outline (collinear outline edges and cuts: the bar of a T under its stem), a
---               list {a1, b1, a2, b2, ...} of the seam parts as fractions of the face, from
---               vertex i (0) to vertex i + 1 (1), ascending and disjoint. Parts may touch:
---               where two meet, at an outline vertex, the point between them is outline.
---               Collider queries (containsPoint, the ray queries) treat seams as inside, not
---               as surfaces; the shape's own queries ignore them. Seams describe the piece's
---               place in the compound it was built for, so they travel with it: copies share
---               the (never changed) table, transforms keep it (fractions do not change), and
---               a piece removed from its Concave keeps it, as do the pieces left (their faces
---               toward the removed one stay seams). An instance has its own only when some
---               face is a seam; the others read their class's false (Shape.checkClass puts
---               it on every class, so that the ray queries, which read it per leaf hit, go one
---               step up the class chain, not all the way). ConvexPolygon:merge carries it
---               over (see _seamsFrom).
local ROOT = (...):match('^(.-)%.base%.[^%.]+$')
local Shape = require(ROOT .. '.base.Shape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')
local AREA, COS, COUNT, DIRTY, HALF = layout.AREA, layout.COS, layout.COUNT, layout.DIRTY, layout.HALF
local NCOS, NSIN, RADIUS = layout.NCOS, layout.NSIN, layout.RADIUS
local ROUND, RSCALE, RX, RY, SCALE = layout.ROUND, layout.RSCALE, layout.RX, layout.RY, layout.SCALE
local SHORT, SIN = layout.SHORT, layout.SIN
local limits = require(ROOT .. '.limits')
local numbers = Shape._numbers

local MINX, MINY, MAXX, MAXY, R = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY, layout.R
local X, Y = layout.X, layout.Y
local STRIDE, FIRST, VY, NX, NY, D = layout.STRIDE, layout.FIRST, layout.VY, layout.NX, layout.NY, layout.D
local BASE = layout.BASE

local sqrt, huge, abs, floor = math.sqrt, math.huge, math.abs, math.floor
local number = check.number
local badSelf, type = check.badSelf, type
local unit, length, TINY2 = limits.unit, limits.length, limits.TINY2

---@class strike.VertexShape : strike.Shape
local VertexShape = Shape:extend()
VertexShape.kind = 'polygon'
VertexShape.name = 'VertexShape'
VertexShape._shortName = 'shortest edge'

--- The empty instance `Class(...)` fills (class.lua): room for the slots of `n` vertices (by
--- default 5; a polygon with more grows once) and for a polygon's named fields (Shape._slots).
--- Subclasses that know their vertex count from their arguments pass it (ConvexPolygon,
--- Rectangle, RegularPolygon): a table that grows is laid out anew.
---@param n integer|nil
---@return table
function VertexShape._alloc(n)
  if type(n) == 'number' and n >= 3 and n <= 64 and n % 1 == 0 then return Shape._slots(layout.size(n)) end
  return Shape._slots(layout.size(5))
end

--- The empty instance of a shape with two vertex records (edges, capsules), as an `_alloc`
--- (class.lua; it ignores the constructor's arguments).
---@return table
function VertexShape._alloc2() return Shape._slots(layout.size(2)) end

--- An empty instance with `n` array slots and room for 8 named fields, for a subclass with
--- slots of its own (ChainSegment).
---@param n integer
---@return table
function VertexShape._allocSlots(n) return Shape._slots(n) end

-- Normals this close to antiparallel are made exactly antiparallel (a change far below
-- any coordinate's rounding noise), so that opposite faces can share one projection.
local ANTIPARALLEL = 1e-10

-- n / 2 when every normal i + n/2 is (nearly) -normal i, snapping those to exactly -normal
-- i; else 0 and the normals stay as they are.
local function symmetricHalf(l, n)
  if n % 2 ~= 0 then return 0 end
  local h = floor(n / 2)
  for k = 3, 4 * h, 4 do -- (k: normal i's x; k + 4h: normal i + h's)
    if abs(l[k] + l[k + 4 * h]) > ANTIPARALLEL or abs(l[k + 1] + l[k + 1 + 4 * h]) > ANTIPARALLEL then return 0 end
  end
  for k = 3, 4 * h, 4 do l[k + 4 * h], l[k + 1 + 4 * h] = -l[k], -l[k + 1] end
  return h
end

-- Local geometry (see the header). `recent` holds the last RECENT tables made, weakly (sharing
-- is invisible: a shape gets the very numbers it would have had, so nothing depends on which
-- are still there), `last` the slot of the newest. A level's tiles, a wave of enemies,
-- bullets: shapes of one size come in runs, and among 20,000 16-by-12 rectangles at random
-- places (bench/space.lua's memory section) the last table made matched 98 % of the time,
-- one of the last 8 99 % (the rounding of the centroid leaves a few variants of the numbers).
local RECENT = 8
local recent = setmetatable({}, { __mode = 'v' })
local last = 0
-- _setVertices works the numbers out in spare[m] (m: how many: 4n and the sizes), a table that
-- becomes the shape's when no recent one matches (then the next shape of that many numbers
-- makes a new one), so that nothing is copied and nothing allocated when one matches; for n up
-- to SPARE (a shape with more makes its table: a spare kept for it would be large).
local SPARE = 16
local spare = {}
local mathType = math.type -- luacheck: ignore 143 (Lua 5.3+: integers and floats)

-- Are g[1..m] and l[1..m] the same numbers, and g no longer? The first 4n are floats (what
-- _setVertices works out), the rest the class's sizes, as the game gave them: an integer and
-- a float of the same value differ there on Lua 5.3+. The sign of a zero is compared too, so
-- that a shared table gives the results an own one would.
local function sameGeometry(g, l, m, n4)
  if g[m + 1] ~= nil then return false end -- (a shorter g fails below: nil is no number)
  for k = 1, n4 do
    local a, b = g[k], l[k]
    if a ~= b or (a == 0 and 1 / a ~= 1 / b) then return false end
  end
  for k = n4 + 1, m do
    local a, b = g[k], l[k]
    if a ~= b or (a == 0 and 1 / a ~= 1 / b) or (mathType and mathType(a) ~= mathType(b)) then return false end
  end
  return true
end

-- The recent table with the numbers l[1..m], of which 4n are vertices and normals, or nil.
local function recentMatch(l, m, n4)
  local l1, j = l[1], last
  for _ = 1, RECENT do -- (the newest first)
    local g = recent[j]
    if g and g[1] == l1 and sameGeometry(g, l, m, n4) then return g end
    j = j > 1 and j - 1 or RECENT
  end
  return nil
end

-- Keep g among the recent tables.
local function remember(g)
  last = last < RECENT and last + 1 or 1
  recent[last] = g
end

--- (internal) The local geometry of n vertices with the numbers l[1..4n] (see the header): one
--- of the last few made when it has those very numbers, else a new table that copies them.
--- `l` itself is never kept, so a caller may pass a scratch table.
---@param l number[]
---@param n integer
---@return number[]
function VertexShape._shareGeometry(l, n)
  local m = 4 * n
  local g = recentMatch(l, m, m)
  if g then return g end
  g = numbers(m)
  for k = 1, m do g[k] = l[k] end
  remember(g)
  return g
end

-- The sizes a subclass gives ConvexPolygon.new for the shape it is building (_sizesNext).
local next1, next2, next3 = nil, nil, nil

--- (internal) The sizes (see the header) of the shape that the next ConvexPolygon.new builds:
--- a subclass that calls it says them just before (nothing runs in between: ConvexPolygon.new
--- takes them first thing, so that no error can leave them for another shape).
---@param size1 number|nil
---@param size2 number|nil
---@param size3 number|nil
function VertexShape._sizesNext(size1, size2, size3) next1, next2, next3 = size1, size2, size3 end

--- (internal) Take the sizes _sizesNext left (nil when none), leaving none.
---@return number|nil, number|nil, number|nil
function VertexShape._takeSizes()
  local a, b, c = next1, next2, next3
  next1, next2, next3 = nil, nil, nil
  return a, b, c
end

--- (internal) The class's sizes kept in the local geometry (see the header), nil where none.
---@return number|nil, number|nil, number|nil
function VertexShape:_sizes()
  local l, m = self._l, 4 * self[COUNT]
  return l[m + 1], l[m + 2], l[m + 3]
end

--- (internal) Give the shape a local geometry of its own, a copy no other shape shares, and
--- return it: for code that changes it in place (S.pace's queryRect probe).
---@return number[]
function VertexShape:_ownGeometry()
  local l, m = self._l, 4 * self[COUNT]
  while l[m + 1] ~= nil do m = m + 1 end -- (the sizes too)
  local own = numbers(m)
  for k = 1, m do own[k] = l[k] end
  self._l = own
  return own
end

--- Store world-space vertices xs, ys (count n, positive winding, validated) as local
--- geometry about the centroid (cx, cy), with the given unscaled area and the class's sizes
--- (up to 3 numbers, nil for none: see the header); the slot SHORT gets the shortest edge (for
--- Shape:_checkNew, which the constructor calls next).
function VertexShape:_setVertices(xs, ys, n, cx, cy, area, size1, size2, size3)
  local n4 = 4 * n
  local m = size3 ~= nil and n4 + 3 or size2 ~= nil and n4 + 2 or size1 ~= nil and n4 + 1 or n4
  local l = spare[m] -- (worked out here, then shared: see `spare`)
  if not l then l = numbers(m) end
  local r2 = 0
  for i = 1, n do
    local x, y = xs[i] - cx, ys[i] - cy
    l[4 * i - 3], l[4 * i - 2] = x, y
    local d2 = x * x + y * y
    if d2 > r2 then r2 = d2 end
  end
  local short = huge
  for i = 1, n do
    local k, j = 4 * i - 3, i < n and 4 * i + 1 or 1
    local ex, ey = l[j] - l[k], l[j + 1] - l[k + 1]
    local len2 = ex * ex + ey * ey
    if len2 >= TINY2 and len2 < huge then
      local len = sqrt(len2)
      l[k + 2], l[k + 3] = ey / len, -ex / len
    else -- (an edge too short or too long for its square: scaled, still unit; see limits.lua)
      local nx, ny = unit(ey, -ex)
      l[k + 2], l[k + 3] = nx or 0.0, ny or -1.0 -- (floats, as every vertex and normal: see sameGeometry)
    end
    -- the shortest edge, from the coordinates as given (what the constructors check)
    local o = i < n and i + 1 or 1
    local e = length(xs[o] - xs[i], ys[o] - ys[i])
    if e < short then short = e end
  end
  local size = layout.size(n)
  if self[1] == nil then -- (zeros already when Shape._slots made it on a VM without table.new)
    for k = 1, size do self[k] = 0 end
  end
  for k = #self, size + 1, -1 do self[k] = nil end
  self[HALF] = symmetricHalf(l, n)
  if m > n4 then -- (only the sizes given: Lua 5.1 keeps a key set to nil)
    l[n4 + 1] = size1
    if m > n4 + 1 then l[n4 + 2] = size2 end
    if m > n4 + 2 then l[n4 + 3] = size3 end
  end
  local g = recentMatch(l, m, n4)
  if g then
    if n <= SPARE then spare[m] = l end
  else
    g = l
    spare[m] = nil
    remember(g)
  end
  self[COUNT], self._l = n, g
  self[AREA], self[RADIUS], self[SHORT] = area, sqrt(r2), short
  self[ROUND] = 0
  -- (no refresh yet: see _refresh and _movedBounds)
  self[NCOS], self[NSIN], self[RX], self[RY], self[RSCALE] = false, false, false, false, false
  self:_setPose(cx, cy)
end

--- Make the shape rounded by r (> 0, unscaled, validated): every point within r of its
--- polygon. Call after _setVertices, with the vertices laid out about the rounded shape's
--- centroid and its AREA slot already the rounded area (geometry/polygon.lua: rounded).
---@param r number
function VertexShape:_setRounding(r)
  self[ROUND] = r + 0.0
  self[RADIUS] = self[RADIUS] + r
  self._kind = 'rounded'
  self[DIRTY] = true
end

function VertexShape:_refresh()
  local n = self[COUNT]
  local c, s, k = self[COS], self[SIN], self[SCALE]
  local x0, y0 = self[X], self[Y]
  local l = self._l
  local minx, miny, maxx, maxy = huge, huge, -huge, -huge
  local sc, ss = c * k, s * k
  -- The world normals are those of the angle they were made for (the slots NCOS, NSIN): a move or a
  -- scale leaves unit normals as they are, so they are turned only when the angle changed.
  local turned = c ~= self[NCOS] or s ~= self[NSIN]
  for i = 1, n do
    local q = 4 * i - 3
    -- (vec.rotate's formula, written out: this loop runs for every vertex of every shape
    -- that moved, and an interpreter pays a call per use; on Lua 5.4 the transforms row of
    -- make bench measured 465-534k bodies/s with the calls, 563-608k without)
    local lx, ly = l[q], l[q + 1]
    local px, py = x0 + sc * lx - ss * ly, y0 + ss * lx + sc * ly
    if px < minx then minx = px end
    if px > maxx then maxx = px end
    if py < miny then miny = py end
    if py > maxy then maxy = py end
    local r = STRIDE * i + BASE
    local nx, ny
    if turned then
      local mx, my = l[q + 2], l[q + 3]
      nx, ny = c * mx - s * my, s * mx + c * my
      self[r + NX], self[r + NY] = nx, ny
    else
      nx, ny = self[r + NX], self[r + NY]
    end
    self[r], self[r + VY], self[r + D] = px, py, nx * px + ny * py
  end
  self[NCOS], self[NSIN] = c, s
  self[RX], self[RY], self[RSCALE] = x0, y0, k -- (the pose refreshed for: see _movedBounds)
  local r = self[ROUND] * k
  self[MINX], self[MINY], self[MAXX], self[MAXY] = minx - r, miny - r, maxx + r, maxy + r
  self[R] = r
  self[DIRTY] = false
end

--- Write the bounds of a shape never refreshed (its slot RX is false) in its bounds slots,
--- the very numbers _refresh would (the same arithmetic), without its vertex records: they
--- wait, the shape staying dirty, for the first reader that needs them (the narrow phase, a
--- ray, a getter), which refreshes it. For S.pace and a collider's bounds, which need only a
--- box for a body just built and added: most of a level is never tested. (A shape refreshed
--- before keeps its last bounds for _movedBounds, which reads them with the pose they were
--- made for: it is refreshed instead; see VertexShape._boundsOnly.)
function VertexShape:_freshBounds()
  local n = self[COUNT]
  local c, s, k = self[COS], self[SIN], self[SCALE]
  local x0, y0 = self[X], self[Y]
  local l = self._l
  local minx, miny, maxx, maxy = huge, huge, -huge, -huge
  local sc, ss = c * k, s * k
  for i = 1, n do
    local q = 4 * i - 3
    local lx, ly = l[q], l[q + 1]
    local px, py = x0 + sc * lx - ss * ly, y0 + ss * lx + sc * ly -- (as _refresh)
    if px < minx then minx = px end
    if px > maxx then maxx = px end
    if py < miny then miny = py end
    if py > maxy then maxy = py end
  end
  local r = self[ROUND] * k
  self[MINX], self[MINY], self[MAXX], self[MAXY] = minx - r, miny - r, maxx + r, maxy + r
end

--- (internal) Bring a dirty shape's bounds slots up to date: by _freshBounds when it was
--- never refreshed and its class refreshes as VertexShape does (a class with a _refresh of its
--- own may bound itself otherwise), else by its _refresh. For the readers that need the bounds
--- alone (strike/space/Space.lua, colliders/Collider.lua).
---@param shape strike.Shape a dirty shape
function VertexShape._boundsOnly(shape)
  if shape[RX] == false and shape._refresh == VertexShape._refresh then
    shape:_freshBounds()
  else
    shape:_refresh()
  end
end

--- The bounds of a dirty shape that has only moved since its last refresh (same angle and
--- scale), without refreshing it: the last bounds moved by the same vector, grown on every
--- side by a rounding's worth, so they hold the bounds a refresh would compute. Returns nil
--- when the shape has turned or scaled, or was never refreshed (then refresh it). For
--- S.pace, which needs only a box for most bodies that move (strike/space/Space.lua).
---@return number|nil minx
---@return number miny
---@return number maxx
---@return number maxy
function VertexShape:_movedBounds()
  local rx = self[RX]
  if rx == false or self[COS] ~= self[NCOS] or self[SIN] ~= self[NSIN] or self[SCALE] ~= self[RSCALE] then
    return nil
  end
  local dx, dy = self[X] - rx, self[Y] - self[RY]
  local x0, y0, x1, y1 = self[MINX] + dx, self[MINY] + dy, self[MAXX] + dx, self[MAXY] + dy
  -- (each bound is a coordinate plus an offset, rounded twice here and once by a refresh)
  local e = 1e-14 * (abs(x0) + abs(y0) + abs(x1) + abs(y1) + abs(dx) + abs(dy))
  return x0 - e, y0 - e, x1 + e, y1 + e
end

-- i is a whole number from 1 to n.
local function inRange(i, n)
  return type(i) == 'number' and i >= 1 and i <= n and i % 1 == 0
end

--- Number of vertices (2 for an Edge).
---@return integer
function VertexShape:getVertexCount()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getVertexCount') end
  return self[COUNT]
end

--- World coordinates of vertex i, or nil when i is out of range (never an error).
---@param i integer
---@return number|nil x, number|nil y
function VertexShape:getVertex(i)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getVertex') end
  if not inRange(i, self[COUNT]) then return nil end
  if self[DIRTY] then self:_refresh() end
  local k = STRIDE * i + BASE
  return self[k], self[k + VY]
end

--- Edge i (vertex i to vertex i + 1, wrapping), as x1, y1, x2, y2; nil when out of range.
--- An Edge has two: 1 is p1 to p2, 2 is p2 to p1.
---@param i integer
---@return number|nil x1, number|nil y1, number|nil x2, number|nil y2
function VertexShape:getEdge(i)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getEdge') end
  local n = self[COUNT]
  if not inRange(i, n) then return nil end
  if self[DIRTY] then self:_refresh() end
  local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
  return self[k], self[k + VY], self[l], self[l + VY]
end

--- Unit outward normal of edge i in world space; nil when out of range.
---@param i integer
---@return number|nil nx, number|nil ny
function VertexShape:getNormal(i)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getNormal') end
  if not inRange(i, self[COUNT]) then return nil end
  if self[DIRTY] then self:_refresh() end
  local k = STRIDE * i + BASE
  return self[k + NX], self[k + NY]
end

--- World vertices as a flat list {x1, y1, x2, y2, ...}, ready for love.graphics.polygon.
--- Fills and returns `out` when given (entries past the vertices are cleared), else a new table.
---@param out number[]|nil
---@return number[] vertices, integer count the number of vertices
function VertexShape:getVertices(out)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getVertices') end
  if self[DIRTY] then self:_refresh() end
  out = out or {}
  if type(out) ~= 'table' or out._type ~= nil then check.badOut('strike.Shape:getVertices', out) end
  local n = self[COUNT]
  for i = 1, n do
    local k = STRIDE * i + BASE
    out[2 * i - 1], out[2 * i] = self[k], self[k + VY]
  end
  for i = #out, 2 * n + 1, -1 do out[i] = nil end
  return out, n
end

--- Minimum and maximum of the shape's projection on the unit vector (nx, ny).
---@param nx number
---@param ny number
---@return number min, number max
function VertexShape:project(nx, ny)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:project') end
  number(nx, 'strike.Shape:project', 'nx')
  number(ny, 'strike.Shape:project', 'ny')
  if self[DIRTY] then self:_refresh() end
  local lo, hi = huge, -huge
  for k = FIRST, STRIDE * self[COUNT] + BASE, STRIDE do
    local d = self[k] * nx + self[k + VY] * ny
    if d < lo then lo = d end
    if d > hi then hi = d end
  end
  local r = self[R] -- (a rounded shape reaches r beyond its core along any unit vector)
  return lo - r, hi + r
end

--- The rounding radius now: the shape is every point within it of its vertices' polygon
--- (0 for a sharp polygon or an edge; a capsule's cap radius).
---@return number
function VertexShape:getRounding()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getRounding') end
  return self[ROUND] * self[SCALE]
end

-- The squared distance from (x, y) to the segment from (x1, y1) to (x2, y2).
local function segmentDistance2(x, y, x1, y1, x2, y2)
  local ex, ey = x2 - x1, y2 - y1
  local px, py = x - x1, y - y1
  local t = px * ex + py * ey
  if t > 0 then
    local e2 = ex * ex + ey * ey
    if t >= e2 then
      px, py = x - x2, y - y2
    else
      t = t / e2
      px, py = px - t * ex, py - t * ey
    end
  end
  return px * px + py * py
end

--- Index of the vertex farthest along (nx, ny); the lowest index wins ties.
---@param nx number
---@param ny number
---@return integer
function VertexShape:getSupport(nx, ny)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:getSupport') end
  if self[DIRTY] then self:_refresh() end
  number(nx, 'strike.Shape:getSupport', 'nx')
  number(ny, 'strike.Shape:getSupport', 'ny')
  local best, bi = -huge, 1
  for i = 1, self[COUNT] do
    local k = STRIDE * i + BASE
    local d = self[k] * nx + self[k + VY] * ny
    if d > best then best, bi = d, i end
  end
  return bi
end

--- True when the point is strictly inside (a point on the boundary is not inside; an Edge
--- has no inside). Takes x, y or a table {x = , y = }.
---@param x number|table
---@param y number|nil
---@return boolean
function VertexShape:containsPoint(x, y)
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:containsPoint') end
  x, y = Shape._point(x, y, 'strike.Shape:containsPoint')
  if self[DIRTY] then self:_refresh() end
  local r, n = self[R], self[COUNT]
  if r > 0 then
    -- rounded: inside when nearer than r to the core (the largest face separation when the
    -- point is in front of some face, else 0: inside the core)
    local best = -huge
    for k = FIRST, STRIDE * n + BASE, STRIDE do
      local s = (x - self[k]) * self[k + NX] + (y - self[k + VY]) * self[k + NY]
      if s > best then best = s end
    end
    if best >= r then return false end
    if best <= 0 and n >= 3 then return true end
    local d2 = huge
    for i = 1, n do -- (the nearest edge: a point beyond a corner is nearest to a vertex)
      local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
      local e = segmentDistance2(x, y, self[k], self[k + VY], self[l], self[l + VY])
      if e < d2 then d2 = e end
    end
    return d2 < r * r
  end
  if n < 3 then return false end
  for k = FIRST, STRIDE * n + BASE, STRIDE do
    if (x - self[k]) * self[k + NX] + (y - self[k + VY]) * self[k + NY] >= 0 then return false end
  end
  return true
end

-- Stateless edge iterator: i, x1, y1, x2, y2.
local function edgeIter(self, i)
  i = i + 1
  local n = self[COUNT]
  if i > n then return nil end
  local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
  return i, self[k], self[k + VY], self[l], self[l + VY]
end

--- Iterate over the edges: `for i, x1, y1, x2, y2 in shape:ipairs() do`.
--- Allocates nothing. The argument is accepted for compatibility and ignored.
---@return function, strike.VertexShape, integer
function VertexShape:ipairs()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:ipairs') end
  if self[DIRTY] then self:_refresh() end
  return edgeIter, self, 0
end

-- Stateless edge-vector iterator: i, dx, dy.
local function vecIter(self, i)
  i = i + 1
  local n = self[COUNT]
  if i > n then return nil end
  local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
  return i, self[l] - self[k], self[l + VY] - self[k + VY]
end

--- Iterate over edge vectors: `for i, dx, dy in shape:vecs() do`. Allocates nothing.
---@return function, strike.VertexShape, integer
function VertexShape:vecs()
  if type(self) ~= 'table' or self._pose == nil then badSelf(self, 'strike.Shape:vecs') end
  if self[DIRTY] then self:_refresh() end
  return vecIter, self, 0
end

--- Largest distance from (px, py) to the shape (to its farthest vertex).
---@param px number
---@param py number
---@return number
function VertexShape:_farthest(px, py)
  if self[DIRTY] then self:_refresh() end
  local best = 0
  for k = FIRST, STRIDE * self[COUNT] + BASE, STRIDE do
    local dx, dy = self[k] - px, self[k + VY] - py
    local d = dx * dx + dy * dy
    if d > best then best = d end
  end
  return sqrt(best) + self[R]
end

-- Seams (see the header) ------------------------------------------------------------------

-- A point is on a seam part when it is farther than SEAM_EPS * (|centroid| + radius) from the
-- part's ends (and, for containsPoint, nearer than that to the face's line): two pieces keep
-- their copies of a shared outline vertex relative to their own centroids, so the copies
-- differ by a rounding of the coordinates, far below this.
local SEAM_EPS = 1e-12
-- _seamsFrom: a source face lies on a face when its ends are within LINE_EPS * radius (plus
-- SEAM_EPS of the coordinates) of the face's line; the hull that builds a ConvexPolygon drops
-- corners that turn by less than 1e-10, so a face may stand for several collinear ones.
local LINE_EPS = 1e-9

--- (internal) The distance within which seam tests call two points one: SEAM_EPS times the
--- centroid's coordinates plus the radius. The shape must be fresh (not dirty).
---@return number
function VertexShape:_seamTolerance()
  return SEAM_EPS * (abs(self[X]) + abs(self[Y]) + self[RADIUS] * self[SCALE])
end

--- (internal) Is the point (px, py), taken to lie on face i's line, on a seam part of face
--- i, farther than the seam tolerance plus `slack` from that part's ends? False when face i
--- has no seam. The shape must be fresh; i a whole number from 1 to n.
---@param i integer
---@param px number
---@param py number
---@param slack number extra distance allowed for the point's own error (0 for exact points)
---@return boolean
function VertexShape:_onSeam(i, px, py, slack)
  local part = self._seams and self._seams[i]
  if not part then return false end
  local n = self[COUNT]
  local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
  local ax, ay = self[k], self[k + VY]
  local ex, ey = self[l] - ax, self[l + VY] - ay
  local len = sqrt(ex * ex + ey * ey)
  local along = ((px - ax) * ex + (py - ay) * ey) / len -- (from vertex i, along the face)
  local tol = self:_seamTolerance() + slack
  if part == true then return along > tol and along < len - tol end
  -- the parts are disjoint and sorted: only the last one starting before the point can hold
  -- it (a binary search: the comb's bar under its teeth has as many parts as teeth)
  local lo, hi, m = 1, #part / 2, 0
  while lo <= hi do
    local mid = floor((lo + hi) / 2)
    if part[2 * mid - 1] * len < along then
      m, lo = mid, mid + 1
    else
      hi = mid - 1
    end
  end
  return m > 0 and along > part[2 * m - 1] * len + tol and along < part[2 * m] * len - tol
end

--- (internal) Is the point (px, py) on a seam part of some face (within the seam tolerance
--- of the face's line, and farther than it from the part's ends)? What a collider's
--- containsPoint adds to "strictly inside some leaf".
---@param px number
---@param py number
---@return boolean
function VertexShape:_onSeams(px, py)
  local seams = self._seams
  if not seams then return false end
  if self[DIRTY] then self:_refresh() end
  local tol = self:_seamTolerance()
  for i = 1, self[COUNT] do
    if seams[i] then
      local k = STRIDE * i + BASE
      local off = (px - self[k]) * self[k + NX] + (py - self[k + VY]) * self[k + NY]
      if off <= tol and off >= -tol and self:_onSeam(i, px, py, 0) then return true end
    end
  end
  return false
end

-- _seamOf sorts up to this many parts by insertion, more by table.sort (sortMany).
local SEAM_SORT = 16

-- Many parts (the bar of a comb under its teeth, which come in any order): the insertion
-- sort would be quadratic, half of a 2,500-tooth comb's Concave on Lua 5.1-5.4. The same
-- order, stable as it is: the parts' numbers sorted by start, then by number. (A function of
-- its own: its closure would make LuaJIT close upvalues on every return of _seamOf, which it
-- does not compile.)
local function sortMany(parts, np)
  local k, idx, copy = np / 2, {}, {}
  for j = 1, k do idx[j] = j end
  table.sort(idx, function(a, b)
    local sa, sb = parts[2 * a - 1], parts[2 * b - 1]
    if sa ~= sb then return sa < sb end
    return a < b
  end)
  for j = 1, np do copy[j] = parts[j] end
  for j = 1, k do
    local o = idx[j]
    parts[2 * j - 1], parts[2 * j] = copy[2 * o - 1], copy[2 * o]
  end
  return parts
end

--- (internal) A face's seam from the seam parts found on it: `parts` (nil when none; flat
--- fractions lo, hi of the face, `np` of them, in any order) on a face `len` long, with the
--- tolerance `tol` (a length). false when there are none, true when one part covers the
--- whole face (within tol at both ends), else the parts sorted by their start (as in the
--- header). Used here and by S.trikers.Concave.
---@param parts number[]|nil
---@param np integer
---@param len number
---@param tol number
---@return boolean|number[]
function VertexShape._seamOf(parts, np, len, tol)
  if not parts then return false end
  if np == 2 and parts[1] * len <= tol and (1 - parts[2]) * len <= tol then return true end
  if np <= 2 * SEAM_SORT then
    for j = 3, np - 1, 2 do -- (insertion sort by start)
      local lo, hi, m = parts[j], parts[j + 1], j - 2
      while m >= 1 and parts[m] > lo do
        parts[m + 2], parts[m + 3] = parts[m], parts[m + 1]
        m = m - 2
      end
      parts[m + 2], parts[m + 3] = lo, hi
    end
    return parts
  end
  return sortMany(parts, np)
end

local seamOf = VertexShape._seamOf

-- _seamsFrom tests every face against every source face up to this many pairs; above it (a
-- large piece of a Concave, every face of which may be a seam) it tests only the pairs that
-- seamPairs finds.
local SEAM_PAIRS = 256

--- The source faces (src and count as _seamsFrom takes them) that can lie on each of this
--- shape's n faces: those of face i are list[first[i] .. first[i + 1] - 1], ascending, each
--- given as the index of its first number in src (5 * q - 4 for source face q). A source face
--- that gives face i a seam part has a point within the tolerance of face i's segment (its ends
--- are within it of the line, and the part lies on the segment), so along any axis its span
--- and face i's, widened by `pad` (at least that tolerance plus rounding), overlap. The spans
--- along the axis (0.8, 0.6) are swept in order (as Concave's candidates do): the pairs found
--- are the overlapping ones, a few per face for faces and source faces on a convex outline
--- (along the axis it is two chains, each of spans that only touch), so that the whole costs
--- O(m log m) for m faces in all instead of n * count tests; the tests themselves are unchanged,
--- in the same order, so the seams are the same.
---@param shape strike.VertexShape
---@param n integer
---@param src table
---@param count integer
---@param pad number
---@return integer[] first
---@return integer[] list
local function seamPairs(shape, n, src, count, pad)
  local lo, hi, order = {}, {}, {}
  for i = 1, n do
    local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
    local a, b = 0.8 * shape[k] + 0.6 * shape[k + VY], 0.8 * shape[l] + 0.6 * shape[l + VY]
    if a > b then a, b = b, a end
    lo[i], hi[i], order[i] = a - pad, b + pad, i
  end
  for q = 1, count do
    local o = 5 * q - 5
    local a, b = 0.8 * src[o + 1] + 0.6 * src[o + 2], 0.8 * src[o + 3] + 0.6 * src[o + 4]
    if a > b then a, b = b, a end
    lo[n + q], hi[n + q], order[n + q] = a, b, n + q
  end
  local m = n + count
  table.sort(order, function(u, v)
    if lo[u] ~= lo[v] then return lo[u] < lo[v] end
    return u < v
  end)
  -- the overlapping (face, source face) pairs, and how many each source face has
  local pf, pq, np, perSrc = {}, {}, 0, {}
  for q = 1, count do perSrc[q] = 0 end
  for s = 1, m do
    local u = order[s]
    local top = hi[u]
    for t = s + 1, m do
      local v = order[t]
      if lo[v] > top then break end
      if (u <= n) ~= (v <= n) then
        local f, q = u, v - n
        if v <= n then f, q = v, u - n end
        np = np + 1
        pf[np], pq[np] = f, q
        perSrc[q] = perSrc[q] + 1
      end
    end
  end
  -- two stable counting sorts: by source face, then by face (so each face's list ascends)
  local at, byQ = {}, {}
  local pos = 1
  for q = 1, count do
    at[q] = pos
    pos = pos + perSrc[q]
  end
  for p = 1, np do
    local q = pq[p]
    byQ[at[q]] = pf[p]
    at[q] = at[q] + 1
  end
  local first, perFace, put = {}, {}, {}
  for i = 1, n do perFace[i] = 0 end
  for p = 1, np do perFace[pf[p]] = perFace[pf[p]] + 1 end
  pos = 1
  for i = 1, n do
    first[i], put[i] = pos, pos
    pos = pos + perFace[i]
  end
  first[n + 1] = pos
  local list, p = {}, 1
  for q = 1, count do
    for _ = 1, perSrc[q] do
      local f = byQ[p]
      list[put[f]] = 5 * q - 4
      put[f] = put[f] + 1
      p = p + 1
    end
  end
  return first, list
end

--- (internal) The `_seams` of this shape (fresh, built) from the seam faces of the shapes it
--- was made of: `src` holds `count` faces as x1, y1, x2, y2, seam (world coordinates of the
--- ends, in the winding of their own polygon; seam: true or a list of parts, as in the
--- header). A source face lies on face i when both of its ends lie on face i's line (within
--- LINE_EPS of the radius) and it runs the same way; its seam parts, mapped to face i's
--- fractions, become face i's. Returns the list, or false when no face got a seam.
---@param src table
---@param count integer
---@return table|false
function VertexShape:_seamsFrom(src, count)
  if self[DIRTY] then self:_refresh() end
  local n = self[COUNT]
  local tol = LINE_EPS * self[RADIUS] * self[SCALE] + self:_seamTolerance()
  local seams, any = {}, false
  local first, list -- (nil: every face against every source face)
  if n * count > SEAM_PAIRS then first, list = seamPairs(self, n, src, count, 4 * tol) end
  for i = 1, n do
    local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
    local ax, ay = self[k], self[k + VY]
    local ex, ey = self[l] - ax, self[l + VY] - ay
    local len2 = ex * ex + ey * ey
    local len = sqrt(len2)
    local parts, np = nil, 0
    local c0, c1 = 1, count
    if first then c0, c1 = first[i], first[i + 1] - 1 end
    for c = c0, c1 do
      local q = list and list[c] or 5 * c - 4
      local rx, ry, sx, sy, seam = src[q] - ax, src[q + 1] - ay, src[q + 2] - ax, src[q + 3] - ay, src[q + 4]
      if (sx - rx) * ex + (sy - ry) * ey > 0 and abs(ex * ry - ey * rx) <= tol * len
        and abs(ex * sy - ey * sx) <= tol * len then
        local f0, f1 = (rx * ex + ry * ey) / len2, (sx * ex + sy * ey) / len2
        local m = seam == true and 1 or #seam - 1
        for j = 1, m, 2 do
          local a, b = f0, f1
          if seam ~= true then a, b = f0 + seam[j] * (f1 - f0), f0 + seam[j + 1] * (f1 - f0) end
          if a < 0 then a = 0 end
          if b > 1 then b = 1 end
          if (b - a) * len > tol then
            parts = parts or {}
            parts[np + 1], parts[np + 2] = a, b
            np = np + 2
          end
        end
      end
    end
    seams[i] = seamOf(parts, np, len, tol)
    any = any or parts ~= nil
  end
  return any and seams
end

return VertexShape
