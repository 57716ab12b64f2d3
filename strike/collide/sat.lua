--- Narrow phase for convex pairs, all writing into an MTV-shaped `out` table and
--- allocating nothing.
---
--- Polygons (and edges, as two-vertex polygons) use the separating axis theorem in its
--- one-sided form (Box2D's b2FindMaxSeparation, Catto, "Contact Manifolds", GDC 2007):
--- for each face i of A, sep_i = min over B's vertices v of n_i . (v - a_i). The largest
--- sep over both shapes' faces is minus the penetration depth; its face normal is the MTV
--- axis. The face normals of A and the negated face normals of B are exactly the face
--- normals of the Minkowski difference A - B, so this is the exact minimum translation,
--- and its sign comes from the face, never from the centroids.
--- Circle against polygon uses the closest feature (face, or vertex Voronoi region), as in
--- Box2D's b2CollidePolygonAndCircle, with the polygon's rounding radius (slot R, 0 unless
--- it is rounded: collide/rounded.lua) added to the circle's; circle against circle uses
--- the centre line.
---
--- Touching (depth exactly 0) is not a collision.
---
--- Reference-face hysteresis: when both shapes' best faces give almost the same depth
--- (within HYSTERESIS times the first shape's size and distance from the origin: round-off,
--- as for a box resting on another), the first shape's face wins, as in Box2D's
--- b2CollidePolygons, so that the face, and the contact ids built on it, do not flip from
--- one frame to the next. The MTV is then longer than the minimum by at most that much.
---
--- Kernels take (a, b, out [, flip]): with `flip` they report the pair as (b, a), which
--- the dispatch table (dispatch.lua) uses for the reversed order of a pair of kinds.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local layout = require(ROOT .. '.base.layout')
local COUNT, DIRTY, HALF = layout.COUNT, layout.DIRTY, layout.HALF
local limits = require(ROOT .. '.limits')

local sqrt, huge, abs = math.sqrt, math.huge, math.abs
local X, Y, R = layout.X, layout.Y, layout.R
local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local STRIDE, FIRST, VY, NX, NY, D = layout.STRIDE, layout.FIRST, layout.VY, layout.NX, layout.NY, layout.D
local BASE = layout.BASE
local TINY2, direction = limits.TINY2, limits.direction

local sat = {}

--- Relative tolerance of the reference-face hysteresis (see the header).
sat.HYSTERESIS = 1e-12
local HYSTERESIS = sat.HYSTERESIS

-- Fill `out`. (nx, ny) is the unit normal from a to b, depth > 0 means overlap. The
-- callers (S.AT, S.triking) set out.collider and out.collided.
local function result(out, a, b, nx, ny, depth, edge)
  local m = abs(depth)
  out.x, out.y, out.nx, out.ny, out.depth = nx * m, ny * m, nx, ny, depth
  out.separating = not (depth > 0) -- luacheck: ignore 581 (NaN depth must read as separating)
  out.edgeIndex = edge
  out.colliderShape, out.collidedShape = a, b
  return out
end
--- result(out, a, b, nx, ny, depth, edge): fill an MTV-shaped table (all but collider and
--- collided) and return it.
sat.result = result

-- Largest, over A's faces, of the smallest signed distance of B's vertices in front of
-- the face; stops early at the first face with nothing of B behind it (>= 0).
--
-- The smallest distance for face i is B's support point in direction -n_i. A's normals
-- turn counter-clockwise from face to face, so that support point moves forward around
-- B (the rotating-calipers argument, Toussaint 1983): after one full scan for face 1,
-- each face walks forward from the previous support while the projection keeps falling.
-- On a convex polygon the projection along the boundary has a single minimum, so the
-- walk stops exactly there. The whole pass costs O(n + m) instead of O(n * m).
-- An Edge's two faces point opposite ways: a half turn, after which the old support is
-- the new maximum, so each of them gets a full scan instead.
local function maxSeparationWalk(A, B)
  -- (the layout's numbers as locals: an interpreter reads a local faster than an upvalue)
  local stride, first, vy, nxOff, nyOff, dOff = STRIDE, FIRST, VY, NX, NY, D
  local na = A[COUNT]
  local lastB = stride * B[COUNT] + BASE
  local best, bi = -huge, 1
  local j, pj -- B's support record (its slot) and its projection
  local full = na == 2 and 2 or 1 -- faces scanned in full
  local k = BASE -- face i's record
  for i = 1, full do
    k = k + stride
    local nx, ny = A[k + nxOff], A[k + nyOff]
    j, pj = first, nx * B[first] + ny * B[first + vy]
    for r = first + stride, lastB, stride do
      local p = nx * B[r] + ny * B[r + vy]
      if p < pj then j, pj = r, p end
    end
    local s = pj - A[k + dOff]
    if s > best then
      best, bi = s, i
      if s >= 0 then return s, i end
    end
  end
  for i = full + 1, na do
    k = k + stride
    local nx, ny = A[k + nxOff], A[k + nyOff]
    pj = nx * B[j] + ny * B[j + vy]
    while true do
      local r = j < lastB and j + stride or first
      local p = nx * B[r] + ny * B[r + vy]
      if p < pj then j, pj = r, p else break end
    end
    local s = pj - A[k + dOff]
    if s > best then
      best, bi = s, i
      if s >= 0 then return s, i end
    end
  end
  return best, bi
end
-- The same by a full scan, O(n * m), with a branch-free inner loop (math.min compiles to
-- one instruction). Under LuaJIT this is the better choice: the walk's data-dependent
-- loop exits make the trace compiler grow a side trace for every path taken (measured on
-- 500 poly-poly pairs with S.AT: 205 KB of machine code in 215 traces for the walk, against
-- 37 KB in 28 traces for this scan; 74 KB in 48 since symmetric polygons take their own
-- loop; out of LuaJIT's default 512 KB area that the whole game shares), while
-- an interpreter pays for every call to math.min and prefers the walk (Lua 5.4, 8-gons:
-- 308k against 164k pairs/s).
local min, max = math.min, math.max
local function maxSeparationScan(A, B)
  local na = A[COUNT]
  local lastB = STRIDE * B[COUNT] + BASE
  local best, bi = -huge, 1
  local h = A[HALF]
  if h > 0 then
    -- Centrally symmetric A: face i + h has the normal -n_i, so one projection of B on n_i
    -- gives both faces: min for face i, -max for face i + h. The result is the one of the
    -- face-by-face scan: the largest separation, the lowest face among ties, and when
    -- something separates, the lowest separating face (face i < h + 1 <= any face i + h).
    local sepI, sepS = 0, 0 -- the first separating face of the second half, if any
    for i = 1, h do
      local k = STRIDE * i + BASE
      local nx, ny = A[k + NX], A[k + NY]
      local lo, hi = huge, -huge
      for r = FIRST, lastB, STRIDE do
        local p = nx * B[r] + ny * B[r + VY]
        lo, hi = min(lo, p), max(hi, p)
      end
      local s = lo - A[k + D]
      if s >= 0 then return s, i end
      if s > best or (s == best and i < bi) then best, bi = s, i end
      local f = i + h
      s = -hi - A[STRIDE * f + BASE + D]
      if s >= 0 then
        if sepI == 0 then sepI, sepS = f, s end
      elseif s > best or (s == best and f < bi) then
        best, bi = s, f
      end
    end
    if sepI > 0 then return sepS, sepI end
    return best, bi
  end
  for i = 1, na do
    local k = STRIDE * i + BASE
    local nx, ny = A[k + NX], A[k + NY]
    local s = huge
    for r = FIRST, lastB, STRIDE do
      s = min(s, nx * B[r] + ny * B[r + VY])
    end
    s = s - A[k + D]
    if s > best then
      best, bi = s, i
      if s >= 0 then return s, i end
    end
  end
  return best, bi
end

local maxSeparation = rawget(_G, 'jit') and maxSeparationScan or maxSeparationWalk
--- maxSeparation(A, B): over A's faces, the largest of the smallest signed distance of B's
--- vertices in front of the face (>= 0: that face separates them), and that face's index.
--- It stops at the first separating face. The variant in use suits the VM; both are here
--- for the specs.
---@type fun(A: strike.VertexShape, B: strike.VertexShape): number, integer
sat.maxSeparation = maxSeparation
--- The walking variant (interpreters).
sat.maxSeparationWalk = maxSeparationWalk
--- The scanning variant (LuaJIT).
sat.maxSeparationScan = maxSeparationScan

-- The size of round-off in A's separations: its distance from the origin plus its extent
-- (abs written out: an interpreter pays a call for math.abs).
local function roundScale(A)
  local x, y = A[X], A[Y]
  if x < 0 then x = -x end
  if y < 0 then y = -y end
  return x + y + (A[MAXX] - A[MINX]) + (A[MAXY] - A[MINY])
end
--- roundScale(A): the size of round-off in A's separations (for the hysteresis).
sat.roundScale = roundScale

--- Polygon (or edge) A against polygon (or edge) B: the face of either with the largest
--- separation gives the MTV (A's face unless B's is larger beyond the hysteresis).
---@param A strike.VertexShape
---@param B strike.VertexShape
---@param out table an MTV-shaped table
---@return table out
function sat.polygonPolygon(A, B, out)
  if A[DIRTY] then A:_refresh() end
  if B[DIRTY] then B:_refresh() end
  local sA, iA = maxSeparation(A, B)
  local k = STRIDE * iA + BASE
  if sA >= 0 then return result(out, A, B, A[k + NX], A[k + NY], -sA, iA) end
  local sB, iB = maxSeparation(B, A)
  if sB > sA and (sB >= 0 or sB - sA > HYSTERESIS * roundScale(A)) then
    k = STRIDE * iB + BASE
    return result(out, A, B, -B[k + NX], -B[k + NY], -sB, -iB)
  end
  return result(out, A, B, A[k + NX], A[k + NY], -sA, iA)
end

-- Polygon P against circle C; when `flip`, report it as C against P.
local function polygonCircle(P, C, out, flip)
  if P[DIRTY] then P:_refresh() end
  if C[DIRTY] then C:_refresh() end
  local cx, cy, r = C[X], C[Y], C[R] + P[R] -- (a rounded P reaches P[R] beyond its core)
  local n = P[COUNT]
  local best, bi = -huge, 1
  local stride, yOff, nxOff, nyOff = STRIDE, VY, NX, NY -- (locals: see maxSeparationWalk)
  local k = BASE
  for i = 1, n do
    k = k + stride
    local s = P[k + nxOff] * (cx - P[k]) + P[k + nyOff] * (cy - P[k + yOff])
    if s > best then
      best, bi = s, i
      if s >= r then break end
    end
  end
  k = STRIDE * bi + BASE
  local nx, ny, depth, edge = P[k + NX], P[k + NY], r - best, bi
  if (best > 0 or n == 2) and best < r then
    -- the centre is outside face bi (or, for an edge, anywhere on its line): the closest
    -- feature is the face or one of its ends
    local l = STRIDE * (bi < n and bi + 1 or 1) + BASE
    local x1, y1, x2, y2 = P[k], P[k + VY], P[l], P[l + VY]
    local vx, vy
    if (cx - x1) * (x2 - x1) + (cy - y1) * (y2 - y1) <= 0 then
      vx, vy = x1, y1
    elseif (cx - x2) * (x1 - x2) + (cy - y2) * (y1 - y2) <= 0 then
      vx, vy = x2, y2
    end
    if vx then
      local dx, dy = cx - vx, cy - vy
      local d2 = dx * dx + dy * dy
      if d2 >= TINY2 and d2 < huge then
        local d = sqrt(d2)
        nx, ny, depth, edge = dx / d, dy / d, r - d, 0
      else -- (a distance whose square is not a normal double: scaled, see strike/limits.lua)
        local ux, uy, d = direction(vx, vy, cx, cy)
        if ux then -- (a centre exactly on the vertex keeps the face normal, depth r)
          nx, ny, depth, edge = ux, uy, r - d, 0
        end
      end
    end
  end
  if flip then return result(out, C, P, -nx, -ny, depth, -edge) end
  return result(out, P, C, nx, ny, depth, edge)
end

--- Polygon (or edge) P against circle C; with `flip`, reported as C against P.
---@param P strike.VertexShape
---@param C strike.Circle
---@param out table
---@param flip boolean|nil
---@return table out
sat.polygonCircle = polygonCircle

--- Circle against circle. Concentric circles get the normal (0, -1).
---@param A strike.Circle
---@param B strike.Circle
---@param out table
---@return table out
function sat.circleCircle(A, B, out)
  if A[DIRTY] then A:_refresh() end
  if B[DIRTY] then B:_refresh() end
  local dx, dy = B[X] - A[X], B[Y] - A[Y]
  local d2 = dx * dx + dy * dy
  local r = A[R] + B[R]
  if d2 >= TINY2 and d2 < huge then
    local d = sqrt(d2)
    return result(out, A, B, dx / d, dy / d, r - d, 0)
  end
  -- (centres so close or so far apart that the square of their distance is not a normal
  -- double, or equal: scaled, see strike/limits.lua)
  local ux, uy, d = direction(A[X], A[Y], B[X], B[Y])
  if ux then return result(out, A, B, ux, uy, r - d, 0) end
  return result(out, A, B, 0, -1, r, 0)
end

return sat
