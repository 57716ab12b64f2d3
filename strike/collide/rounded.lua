--- Narrow phase for rounded shapes: a capsule, a rounded rectangle or polygon is a convex
--- core (a segment or a polygon: its vertex records) and a radius r (slot R), the set of
--- points within r of the core, as Box2D's rounded polygons and capsules are (b2Polygon's
--- radius; Catto, "Contact Manifolds", GDC 2007, on rounded shapes). Against another core
--- B with radius rB (0 for a sharp polygon, an edge or a chain segment):
---
---  * Cores overlapping: the Minkowski difference of the two shapes is the difference of
---    the cores grown by r = rA + rB, so the penetration is the cores' (the SAT of
---    sat.lua: the largest face separation s < 0) plus r, along the same face normal:
---    depth = r - s, exact.
---  * Cores apart: the shapes overlap when the cores are nearer than r. Any face
---    separation s is at most their distance, so s >= r means no collision at once;
---    otherwise the distance d is the smallest over each core's vertices against the
---    other's edges (O(n m), only for pairs this close), and depth = r - d along the line
---    between the two nearest points: that face's normal when a vertex is nearest to the
---    inside of an edge (edgeIndex names the face, as for polygons), the vertex-to-vertex
---    direction otherwise (edgeIndex 0).
---
--- Circles against rounded shapes use sat.polygonCircle, which adds the polygon's radius to
--- the circle's (the same closest-feature test). Written for strike; allocates nothing.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local sat = require(ROOT .. '.collide.sat')
local layout = require(ROOT .. '.base.layout')
local COUNT, DIRTY = layout.COUNT, layout.DIRTY
local limits = require(ROOT .. '.limits')

local sqrt, huge = math.sqrt, math.huge
local R = layout.R
local STRIDE, VY, NX, NY = layout.STRIDE, layout.VY, layout.NX, layout.NY
local BASE = layout.BASE
local result, maxSeparation, roundScale = sat.result, sat.maxSeparation, sat.roundScale
local HYSTERESIS, TINY2, direction = sat.HYSTERESIS, limits.TINY2, limits.direction

local rounded = {}

-- The point of P's core boundary nearest (px, py): squared distance, the point, and the
-- face whose inside it is on (0 when it is a vertex). For a segment core (two faces, one
-- segment), the face whose normal faces the point.
local function nearestOnCore(P, px, py)
  local n = P[COUNT]
  local best, bx, by, bf = huge, 0, 0, 0
  for i = 1, n do
    local k, l = STRIDE * i + BASE, STRIDE * (i < n and i + 1 or 1) + BASE
    local x1, y1 = P[k], P[k + VY]
    local ex, ey = P[l] - x1, P[l + VY] - y1
    local dx, dy = px - x1, py - y1
    local t, e2 = dx * ex + dy * ey, ex * ex + ey * ey
    local qx, qy, f = x1, y1, 0
    if t > 0 then
      if t >= e2 then
        qx, qy = P[l], P[l + VY]
      elseif P[k + NX] * dx + P[k + NY] * dy >= 0 then
        t = t / e2
        qx, qy, f = x1 + t * ex, y1 + t * ey, i
      else
        t = -1 -- (the other face of a segment core: it gives this point)
      end
    end
    if t ~= -1 then
      local ux, uy = px - qx, py - qy
      local d2 = ux * ux + uy * uy
      if d2 < best then best, bx, by, bf = d2, qx, qy, f end
    end
  end
  return best, bx, by, bf
end

-- Cores apart (some face separation s >= 0 below r): the nearest points. Fills `out` for
-- (A, B), or for (B, A) when `flip`. (sx, sy, s): the separating face's normal (from A
-- toward B) and separation, for cores that touch (distance 0).
local function apart(A, B, out, flip, r, sx, sy, s)
  local best, ax, ay, bx, by, edge = huge, 0, 0, 0, 0, 0
  for j = 1, B[COUNT] do
    local q = STRIDE * j + BASE
    local px, py = B[q], B[q + VY]
    local d2, qx, qy, f = nearestOnCore(A, px, py)
    if d2 < best then best, ax, ay, bx, by, edge = d2, qx, qy, px, py, f end
  end
  for i = 1, A[COUNT] do
    local q = STRIDE * i + BASE
    local px, py = A[q], A[q + VY]
    local d2, qx, qy, f = nearestOnCore(B, px, py)
    if d2 < best then best, ax, ay, bx, by, edge = d2, px, py, qx, qy, -f end
  end
  local nx, ny, d
  if edge > 0 then -- B's vertex over A's face: the face normal, the distance along it
    local k = STRIDE * edge + BASE
    nx, ny = A[k + NX], A[k + NY]
    d = nx * (bx - A[k]) + ny * (by - A[k + VY])
  elseif edge < 0 then
    local k = STRIDE * -edge + BASE
    nx, ny = -B[k + NX], -B[k + NY]
    d = nx * (B[k] - ax) + ny * (B[k + VY] - ay)
  elseif best >= TINY2 and best < huge then
    d = sqrt(best)
    nx, ny = (bx - ax) / d, (by - ay) / d
  else -- (a distance whose square is not a normal double: scaled, see limits.lua)
    nx, ny, d = direction(ax, ay, bx, by)
    if not nx then nx, ny, d = sx, sy, s end -- (the cores touch: the separating face)
  end
  if flip then return result(out, B, A, -nx, -ny, r - d, -edge) end
  return result(out, A, B, nx, ny, r - d, edge)
end

--- A (rounded, or a polygon, an edge, a chain segment) against B (likewise), at least one
--- of them rounded; with `flip`, reported as B against A. See the header.
---@param A strike.VertexShape
---@param B strike.VertexShape
---@param out table an MTV-shaped table
---@param flip boolean|nil
---@return table out
function rounded.collide(A, B, out, flip)
  if A[DIRTY] then A:_refresh() end
  if B[DIRTY] then B:_refresh() end
  local r = A[R] + B[R]
  local sA, iA = maxSeparation(A, B)
  local k = STRIDE * iA + BASE
  local nx, ny, s, edge = A[k + NX], A[k + NY], sA, iA
  if sA < 0 then
    local sB, iB = maxSeparation(B, A)
    if sB > sA and (sB >= 0 or sB - sA > HYSTERESIS * roundScale(A)) then
      k = STRIDE * iB + BASE
      nx, ny, s, edge = -B[k + NX], -B[k + NY], sB, -iB
    end
  end
  if s >= 0 and s < r then return apart(A, B, out, flip, r, nx, ny, s) end
  -- (cores overlapping: exact along the face; s >= r: apart by at least s - r)
  if flip then return result(out, B, A, -nx, -ny, r - s, -edge) end
  return result(out, A, B, nx, ny, r - s, edge)
end

return rounded
