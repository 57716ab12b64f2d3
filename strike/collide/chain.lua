--- Narrow phase for chain segments (strike/base/ChainSegment.lua): one-sided segments
--- with ghost vertices, the technique of Erin Catto, "Ghost Collisions" (Box2D blog, June
--- 2020, https://box2d.org/posts/2020/06/ghost-collisions/), as Box2D v3's chain segments
--- use it. Written for strike; it writes into an MTV-shaped `out` and allocates nothing.
---
--- A chain segment S has the endpoints p1, p2 and the free-side normal n (face 1's).
--- Against a polygon, an edge, a rounded shape or a circle B, with m the MTV normal from S
--- toward B (a rounded shape's measures below reach its radius further):
---  1. The ordinary edge test (sat.lua, S as a two-vertex polygon). A separating result
---     is returned as it is.
---  2. One-sided: when B's centroid is behind S's line, n . (c - p1) < 0, there is no
---     collision (a separating result with depth 0: no gap is measured).
---  3. Ghost vertices: m is admissible when m == n (|cross(n, m)| <= 1e-12), or when m
---     lies in the cone of normals of a convex corner: at p1 from the previous segment's
---     normal to n, at p2 from n to the next segment's normal (1e-12 slack). An open end
---     counts as convex, like a lone edge's end, with the outward tangent in place of the
---     missing neighbour's normal (the free half of the lone edge's end cap). An
---     admissible result is returned as it is.
---  4. Otherwise, when m leans toward a convex corner that has a neighbour (cross(n, m) < 0
---     for p1, > 0 for p2), B reaches past that corner (beyond p1 or p2 along the
---     segment), and the neighbour's normal g separates B from the corner more than n does
---     (min over B of g . (v - corner) > min over B of n . (v - p1)), the contact belongs
---     to the neighbour segment, which reports it: no collision from S (depth 0). This is
---     Box2D's "the neighbour owns it" (skip) case; without it a body that has just
---     passed a hilltop would be pushed back along the previous segment's normal.
---  5. Otherwise (concave corners, normals behind the free side, open ends) the result is
---     replaced by the push along n: depth = how far B reaches behind S's line (polygons:
---     -min over the vertices of n . (v - p1); circles: r - n . (c - p1)), a collision when
---     depth > 0, edge index 1 (S's face 1; -1 when S is the second argument), normal n
---     (-n when S is the second argument: the MTV points from the first toward the second).
--- Chain segments never collide with each other.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local sat = require(ROOT .. '.collide.sat')
local layout = require(ROOT .. '.base.layout')
local CONVEX1, CONVEX2, G1X, G1Y = layout.CONVEX1, layout.CONVEX2, layout.G1X, layout.G1Y
local G2X, G2Y, HASNEXT, HASPREV = layout.G2X, layout.G2Y, layout.HASNEXT, layout.HASPREV
local COUNT, DIRTY = layout.COUNT, layout.DIRTY

local result, polygonPolygon, polygonCircle = sat.result, sat.polygonPolygon, sat.polygonCircle
local roundedCollide = require(ROOT .. '.collide.rounded').collide
local huge = math.huge
local X, Y, R = layout.X, layout.Y, layout.R
local STRIDE, FIRST, VY, NX, NY = layout.STRIDE, layout.FIRST, layout.VY, layout.NX, layout.NY
local BASE = layout.BASE
-- A segment's p1 (with face 1's normal n, the segment's own) and p2 records.
local P1, P2 = layout.base(1), layout.base(2)

local chain = {}

-- Slack of the admissibility tests, on cross products of unit vectors (sines).
local TOL = 1e-12

-- Is m (unit, from S toward the other shape) admissible for S? (S is refreshed.)
local function admissible(S, mx, my)
  local nx, ny = S[P1 + NX], S[P1 + NY]
  local c = nx * my - ny * mx -- cross(n, m) = m . e: < 0 leans toward p1, > 0 toward p2
  if c <= TOL and c >= -TOL and nx * mx + ny * my > 0 then return true end
  if c < 0 then
    return S[CONVEX1] and S[G1X] * my - S[G1Y] * mx >= -TOL -- cross(g1, m) >= 0
  end
  return S[CONVEX2] and mx * S[G2Y] - my * S[G2X] >= -TOL -- cross(m, g2) >= 0
end

--- admissible(segment, mx, my): true when the unit normal (mx, my), pointing from the chain
--- segment toward the other shape, is one the segment may push along (step 3 above). The
--- segment must be refreshed.
---@param S strike.ChainSegment
---@param mx number
---@param my number
---@return boolean
chain.admissible = admissible

-- Steps 4 and 5 for a polygon P (rounded by P[R], 0 for a sharp one: every measure of P
-- reaches that much further): false when the neighbour owns the contact, else the depth
-- of the push along n.
local function polygonVerdict(S, P, mx, my)
  local nx, ny, x1, y1 = S[P1 + NX], S[P1 + NY], S[P1], S[P1 + VY]
  local lastP = STRIDE * P[COUNT] + BASE
  local rp = P[R]
  local sepN = huge
  for r = FIRST, lastP, STRIDE do
    local s = nx * (P[r] - x1) + ny * (P[r + VY] - y1)
    if s < sepN then sepN = s end
  end
  sepN = sepN - rp
  local c = nx * my - ny * mx
  if c < 0 and S[HASPREV] and S[CONVEX1] then
    local gx, gy = S[G1X], S[G1Y]
    local reach, sepG = huge, huge -- reach: min over P of e . (v - p1), e = (-ny, nx)
    for k = FIRST, lastP, STRIDE do
      local dx, dy = P[k] - x1, P[k + VY] - y1
      local r, s = nx * dy - ny * dx, gx * dx + gy * dy
      if r < reach then reach = r end
      if s < sepG then sepG = s end
    end
    if reach - rp < 0 and sepG - rp > sepN then return false end
  elseif c > 0 and S[HASNEXT] and S[CONVEX2] then
    local gx, gy = S[G2X], S[G2Y]
    local x2, y2 = S[P2], S[P2 + VY]
    local reach, sepG = -huge, huge -- reach: max over P of e . (v - p2)
    for k = FIRST, lastP, STRIDE do
      local dx, dy = P[k] - x2, P[k + VY] - y2
      local r, s = nx * dy - ny * dx, gx * dx + gy * dy
      if r > reach then reach = r end
      if s < sepG then sepG = s end
    end
    if reach + rp > 0 and sepG - rp > sepN then return false end
  end
  return -sepN
end

-- The same for a circle C.
local function circleVerdict(S, C, mx, my)
  local nx, ny, x1, y1 = S[P1 + NX], S[P1 + NY], S[P1], S[P1 + VY]
  local cx, cy, r = C[X], C[Y], C[R]
  local dx, dy = cx - x1, cy - y1
  local sepN = nx * dx + ny * dy - r
  local c = nx * my - ny * mx
  if c < 0 and S[HASPREV] and S[CONVEX1] then
    if nx * dy - ny * dx - r < 0 and S[G1X] * dx + S[G1Y] * dy - r > sepN then return false end
  elseif c > 0 and S[HASNEXT] and S[CONVEX2] then
    dx, dy = cx - S[P2], cy - S[P2 + VY]
    if nx * dy - ny * dx + r > 0 and S[G2X] * dx + S[G2Y] * dy - r > sepN then return false end
  end
  return -sepN
end

-- Is the point (x, y) behind S's line?
local function behind(S, x, y)
  return S[P1 + NX] * (x - S[P1]) + S[P1 + NY] * (y - S[P1 + VY]) < 0
end

-- Steps 2 to 5 of the header, after the ordinary edge test filled `out` for (S, B), or
-- for (B, S) when `flip`. `verdict` measures the push along n for B's kind.
local function ghostRules(S, B, out, flip, verdict)
  if out.separating then return out end
  local k = flip and -1 or 1 -- the MTV points from the first argument to the second
  local nx, ny = k * S[P1 + NX], k * S[P1 + NY]
  local first, second = S, B
  if flip then first, second = B, S end
  if behind(S, B[X], B[Y]) then return result(out, first, second, nx, ny, 0, k) end
  local mx, my = k * out.nx, k * out.ny
  if admissible(S, mx, my) then return out end
  return result(out, first, second, nx, ny, verdict(S, B, mx, my) or 0, k)
end

--- Chain segment S against polygon (or edge) P; with `flip`, reported as P against S.
---@param S strike.ChainSegment
---@param P strike.VertexShape
---@param out table an MTV-shaped table
---@param flip boolean|nil
---@return table out
function chain.chainPolygon(S, P, out, flip)
  local m = flip and polygonPolygon(P, S, out) or polygonPolygon(S, P, out)
  return ghostRules(S, P, m, flip, polygonVerdict)
end

--- Chain segment S against a rounded shape P (collide/rounded.lua); with `flip`, reported
--- as P against S.
---@param S strike.ChainSegment
---@param P strike.VertexShape
---@param out table an MTV-shaped table
---@param flip boolean|nil
---@return table out
function chain.chainRounded(S, P, out, flip)
  local m = flip and roundedCollide(P, S, out) or roundedCollide(S, P, out)
  return ghostRules(S, P, m, flip, polygonVerdict)
end

--- Chain segment S against circle C; with `flip`, reported as C against S.
---@param S strike.ChainSegment
---@param C strike.Circle
---@param out table an MTV-shaped table
---@param flip boolean|nil
---@return table out
function chain.chainCircle(S, C, out, flip)
  return ghostRules(S, C, polygonCircle(S, C, out, flip), flip, circleVerdict)
end

--- Two chain segments never collide: a separating result with depth 0 along A's normal.
---@param A strike.ChainSegment
---@param B strike.ChainSegment
---@param out table an MTV-shaped table
---@return table out
function chain.chainChain(A, B, out)
  if A[DIRTY] then A:_refresh() end
  return result(out, A, B, A[P1 + NX], A[P1 + NY], 0, 1)
end

return chain
