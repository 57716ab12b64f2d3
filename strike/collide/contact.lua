--- Contact manifolds: where two colliding convex shapes touch, from their MTV.
---
--- Polygons (and edges) use reference-face clipping (Catto, "Contact Manifolds", GDC 2007;
--- the same scheme as Box2D's b2ClipPolygons and dyn4j's clipping solver): the reference
--- face is the one the separating-axis test found, the MTV's edgeIndex (face i of the first
--- shape for i > 0, face -i of the second for i < 0; the test's hysteresis keeps it from
--- flipping between frames, see sat.lua); the incident face is the other shape's face most
--- opposed to it; the incident face is clipped to the reference face's side planes and
--- the points behind the reference face are kept. Only an MTV that names no face (one made
--- by hand) has its reference face looked up: the face of either shape most aligned with
--- the normal, the first shape's unless the second's is better by 1e-6 in cosine. Circles
--- give one point.
---
--- The kernels are registered per pair of kinds in dispatch.lua, as
--- contact(A, B, nx, ny, depth, edge, out) -> count, with (nx, ny) the unit normal from A
--- toward B and `edge` the MTV's edgeIndex for (A, B).
---
--- Every point lies midway between the two surfaces: half its depth in front of the
--- incident feature, half behind the reference one. (A compound MTV's points, from
--- contact.pushed, are where each member pair touches once the second body has moved by the
--- MTV: the same clipping, with each pair's own face, on the shapes as they are after that
--- move; midway between surfaces that then touch is on both.) Its id names the features
--- that made it, so it stays the same while the same features touch:
---   id = ((side * 65536 + referenceFace) * 65536 + incidentFace) * 4 + corner
--- side 0 when the reference face is the first shape's, 1 when the second's; corner 0 or 1
--- for an incident vertex kept as it is, 2 or 3 for a point cut by the reference face's
--- first or second side plane. A circle's point has id = 2 * face (centre over that face of
--- the polygon) or 2 * vertex + 1 (over that vertex), and 0 for two circles.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local layout = require(ROOT .. '.base.layout')
local COUNT = layout.COUNT

local contact = {}

local sqrt, huge = math.sqrt, math.huge
local X, Y, R = layout.X, layout.Y, layout.R
local VY, NX, NY = layout.VY, layout.NX, layout.NY
local STRIDE, BASE = layout.STRIDE, layout.BASE

-- Write point k of `out`, reusing its table: the tables of points past a list's count wait
-- in the list out._spares (strike/init.lua moves them there), so that #out is always the
-- count and nothing is allocated once a list has held as many points.
local function setPoint(out, k, x, y, depth, id)
  local p = out[k]
  if not p then
    local spares = out._spares
    local n = spares and #spares or 0
    if n > 0 then
      p, spares[n] = spares[n], nil
    else
      p = { x = 0, y = 0, depth = 0, id = 0, nx = 0, ny = 0, colliderShape = false, collidedShape = false }
    end
    out[k] = p
  end
  p.x, p.y, p.depth, p.id = x, y, depth, id
end

-- The face of polygon P whose normal is most aligned with (nx, ny), and that cosine.
local function alignedFace(P, nx, ny)
  local best, bi = -huge, 1
  for i = 1, P[COUNT] do
    local k = STRIDE * i + BASE
    local d = P[k + NX] * nx + P[k + NY] * ny
    if d > best then best, bi = d, i end
  end
  return bi, best
end

-- Clip the segment a-b to where the signed distances da, db are >= 0: a cut end gets the
-- corner `tag`. Nothing (nil) when both ends are outside.
local function clip(ax, ay, bx, by, ca, cb, da, db, tag)
  if da < 0 and db < 0 then return nil end
  if da < 0 then
    local s = da / (da - db)
    ax, ay, ca = ax + s * (bx - ax), ay + s * (by - ay), tag
  elseif db < 0 then
    local s = db / (db - da)
    bx, by, cb = bx + s * (ax - bx), by + s * (ay - by), tag
  end
  return ax, ay, bx, by, ca, cb
end

-- Clip and keep, with Ref the reference polygon (face r) and I the incident one (face f),
-- writing points k0 + 1, ... of `out`. Returns the number of points written. `side` is 0 or
-- 1 (see the header); `flip` turns it (the pair is reported the other way round, see
-- contact.polygons). Ref is taken as moved by (rox, roy) and I by (iox, ioy) (both 0 but for
-- a compound's contacts, contact.pushed); a point is kept when it is less than `slack` in
-- front of the reference surface, and its depth is `depth` when given, else its own.
local function clipFaces(out, k0, Ref, r, rox, roy, I, f, iox, ioy, side, flip, slack, depth)
  if flip then side = 1 - side end
  local rk, rl = STRIDE * r + BASE, STRIDE * (r < Ref[COUNT] and r + 1 or 1) + BASE
  local v1x, v1y, v2x, v2y = Ref[rk] + rox, Ref[rk + VY] + roy, Ref[rl] + rox, Ref[rl + VY] + roy
  local nx, ny = Ref[rk + NX], Ref[rk + NY]
  local tx, ty = v2x - v1x, v2y - v1y
  local len = sqrt(tx * tx + ty * ty)
  tx, ty = tx / len, ty / len
  local ik, il = STRIDE * f + BASE, STRIDE * (f < I[COUNT] and f + 1 or 1) + BASE
  local ax, ay, bx, by = I[ik] + iox, I[ik + VY] + ioy, I[il] + iox, I[il + VY] + ioy
  local ca, cb = 0, 1 -- which corner each end is (see the header)
  local ax0, ay0, bx0, by0 = ax, ay, bx, by
  -- side plane 1: dot(t, p - v1) >= 0
  local lo = tx * v1x + ty * v1y
  ax, ay, bx, by, ca, cb = clip(ax, ay, bx, by, ca, cb, tx * ax + ty * ay - lo, tx * bx + ty * by - lo, 2)
  if ax then
    -- side plane 2: dot(t, p - v2) <= 0
    local hi = tx * v2x + ty * v2y
    ax, ay, bx, by, ca, cb = clip(ax, ay, bx, by, ca, cb, hi - (tx * ax + ty * ay), hi - (tx * bx + ty * by), 3)
  end
  if not ax then
    if not depth then return 0 end
    -- (a compound's pair touches, a corner at an end of the reference face, and round-off
    -- put the whole incident face past that end: its nearer end, below, and nothing else)
    ax, ay, bx, by, ca, cb, slack = ax0, ay0, bx0, by0, 0, 1, -huge
  end
  -- keep what is behind the reference face (rounded shapes: their surfaces are rr in front
  -- of the reference core's face and ri in front of the incident core's, so a point is
  -- kept when its core separation s is below rr + ri, at depth rr + ri - s, midway between
  -- the surfaces; both are 0 for sharp polygons)
  local rr, ri = Ref[R], I[R]
  local reach = rr + ri
  local off = nx * v1x + ny * v1y
  local idBase = ((side * 65536 + r) * 65536 + f) * 4
  local k = k0
  local sa = nx * ax + ny * ay - off
  if sa < reach + slack then
    k = k + 1
    local h = (rr - ri - sa) / 2
    setPoint(out, k, ax + nx * h, ay + ny * h, depth or reach - sa, idBase + ca)
  end
  local sb = nx * bx + ny * by - off
  -- (a compound's pair: not the same point twice, where a corner meets a corner)
  local twice = depth and k > k0 and (bx - ax) * (bx - ax) + (by - ay) * (by - ay) <= slack * slack
  if sb < reach + slack and not twice then
    k = k + 1
    local h = (rr - ri - sb) / 2
    setPoint(out, k, bx + nx * h, by + ny * h, depth or reach - sb, idBase + cb)
  end
  if k == k0 and depth then
    -- (a compound's pair touches, yet round-off left both ends in front, or cut both off:
    -- the nearer one)
    k = k + 1
    if sb < sa then ax, ay, sa, ca = bx, by, sb, cb end
    local h = (rr - ri - sa) / 2
    setPoint(out, k, ax + nx * h, ay + ny * h, depth, idBase + ca)
  end
  return k - k0
end

-- The feature of polygon P nearest the point (cx, cy) as an id: 2 * face or 2 * vertex + 1.
local function circleFeature(P, cx, cy)
  local n = P[COUNT]
  local best, bi = -huge, 1
  for i = 1, n do
    local k = STRIDE * i + BASE
    local s = P[k + NX] * (cx - P[k]) + P[k + NY] * (cy - P[k + VY])
    if s > best then best, bi = s, i end
  end
  local j = bi < n and bi + 1 or 1
  local k, l = STRIDE * bi + BASE, STRIDE * j + BASE
  local x1, y1, x2, y2 = P[k], P[k + VY], P[l], P[l + VY]
  if (cx - x1) * (x2 - x1) + (cy - y1) * (y2 - y1) <= 0 then return 2 * bi + 1 end
  if (cx - x2) * (x1 - x2) + (cy - y2) * (y1 - y2) <= 0 then return 2 * j + 1 end
  return 2 * bi
end

--- Polygon (or edge, or chain segment) A against polygon B: reference-face clipping.
---@param A strike.VertexShape
---@param B strike.VertexShape
---@param nx number
---@param ny number
---@param depth number
---@param edge integer
---@param out table
---@param flip boolean|nil the MTV names B first: the ids' side is turned to match it
---@return integer count
function contact.polygons(A, B, nx, ny, depth, edge, out, flip)
  local k
  if edge > 0 then
    local k0 = STRIDE * edge + BASE
    k = clipFaces(out, 0, A, edge, 0, 0, B, (alignedFace(B, -A[k0 + NX], -A[k0 + NY])), 0, 0, 0, flip, 0)
  elseif edge < 0 then
    local k0 = STRIDE * (-edge) + BASE
    k = clipFaces(out, 0, B, -edge, 0, 0, A, (alignedFace(A, -B[k0 + NX], -B[k0 + NY])), 0, 0, 1, flip, 0)
  else -- (an MTV made by hand: look the reference face up)
    local fa, alignA = alignedFace(A, nx, ny)
    local fb, alignB = alignedFace(B, -nx, -ny)
    if alignB > alignA + 1e-6 then
      local k0 = STRIDE * fb + BASE
      k = clipFaces(out, 0, B, fb, 0, 0, A, (alignedFace(A, -B[k0 + NX], -B[k0 + NY])), 0, 0, 1, flip, 0)
    else
      local k0 = STRIDE * fa + BASE
      k = clipFaces(out, 0, A, fa, 0, 0, B, (alignedFace(B, -A[k0 + NX], -A[k0 + NY])), 0, 0, 0, flip, 0)
    end
  end
  if k == 0 then
    -- Round-off left nothing behind the face: report the deepest vertex of B.
    local best, bj = huge, 1
    for j = 1, B[COUNT] do
      local q = STRIDE * j + BASE
      local p = nx * B[q] + ny * B[q + VY]
      if p < best then best, bj = p, j end
    end
    local q = STRIDE * bj + BASE
    local h = depth / 2 - B[R] -- (from B's core to midway between the surfaces)
    setPoint(out, 1, B[q] + nx * h, B[q + VY] + ny * h, depth, bj)
    k = 1
  end
  return k
end

-- Cosine above which the normal is a face's: the manifold is clipped from faces.
local ALIGNED = 1 - 1e-9

--- A rounded shape (collide/rounded.lua) against a rounded shape or a polygon: clipping as
--- for polygons (contact.polygons, the cores' faces, the radii added) when the normal is
--- a face's; otherwise the rounded corners touch, and the one point is midway between
--- them: A's core vertex farthest along the normal pushed out by A's radius, and B's
--- farthest against it pushed back by B's; its id is ((2 * 65536 + a) * 65536 + b) * 4 for
--- the vertices a of the MTV's first shape and b of its second (side 2).
---@param A strike.VertexShape
---@param B strike.VertexShape
---@param nx number
---@param ny number
---@param depth number
---@param edge integer
---@param out table
---@param flip boolean|nil the MTV names B first
---@return integer count
function contact.rounded(A, B, nx, ny, depth, edge, out, flip)
  if edge ~= 0 then return contact.polygons(A, B, nx, ny, depth, edge, out, flip) end
  local _, alignA = alignedFace(A, nx, ny)
  local _, alignB = alignedFace(B, -nx, -ny)
  if alignA >= ALIGNED or alignB >= ALIGNED then return contact.polygons(A, B, nx, ny, depth, edge, out, flip) end
  local ia, ib, pa, pb = 1, 1, -huge, huge
  for i = 1, A[COUNT] do
    local q = STRIDE * i + BASE
    local p = nx * A[q] + ny * A[q + VY]
    if p > pa then pa, ia = p, i end
  end
  for j = 1, B[COUNT] do
    local q = STRIDE * j + BASE
    local p = nx * B[q] + ny * B[q + VY]
    if p < pb then pb, ib = p, j end
  end
  local qa, qb = STRIDE * ia + BASE, STRIDE * ib + BASE
  local ra, rb = A[R], B[R]
  local x = (A[qa] + nx * ra + B[qb] - nx * rb) / 2
  local y = (A[qa + VY] + ny * ra + B[qb + VY] - ny * rb) / 2
  if flip then ia, ib = ib, ia end
  setPoint(out, 1, x, y, depth, ((2 * 65536 + ia) * 65536 + ib) * 4)
  return 1
end

--- Polygon (or edge, or chain segment) P against circle C: one point, midway between the
--- circle and the polygon's surface along the normal.
---@param P strike.VertexShape
---@param C strike.Circle
---@param nx number
---@param ny number
---@param depth number
---@param edge integer
---@param out table
---@return integer count
function contact.polygonCircle(P, C, nx, ny, depth, edge, out) -- luacheck: ignore 212 (edge)
  local r = C[R]
  setPoint(out, 1, C[X] - nx * (r - depth / 2), C[Y] - ny * (r - depth / 2), depth, circleFeature(P, C[X], C[Y]))
  return 1
end

--- Circle A against circle B: one point, midway between them on the centre line.
---@param A strike.Circle
---@param B strike.Circle
---@param nx number
---@param ny number
---@param depth number
---@param edge integer
---@param out table
---@return integer count
function contact.circles(A, B, nx, ny, depth, edge, out) -- luacheck: ignore 212 (B, edge)
  local r = A[R]
  setPoint(out, 1, A[X] + nx * (r - depth / 2), A[Y] + ny * (r - depth / 2), depth, 0)
  return 1
end

-- A shape's core as one point, when it is one (a circle's centre; a segment of length 0):
-- its x, y; else nil.
local function corePoint(P)
  local n = P[COUNT]
  if not n then return P[X], P[Y] end
  local k, l = STRIDE + BASE, 2 * STRIDE + BASE
  if n == 2 and P[k] == P[l] and P[k + VY] == P[l + VY] then return P[k], P[k + VY] end
  return nil
end

-- Core vertex i of P (a circle's centre for any i).
local function coreVertex(P, i)
  if not P[COUNT] then return P[X], P[Y] end
  local k = STRIDE * i + BASE
  return P[k], P[k + VY]
end

--- The points of one member pair (A of the first body, B of the second) of a compound MTV,
--- where the pair touches once B has moved by (tx, ty) (collide/compound.lua): written to
--- `out` after index k0; returns how many (1 or 2). The pair's own normal (nx, ny) (from A
--- toward B), its depth and the feature it touches along come from outline.feature:
--- `face` > 0, face `face` of A; < 0, face -face of B; 0, core vertex ia of A against core
--- vertex ib of B. Along a face, its incident face is clipped as in contact.polygons, with
--- both shapes where they are after the move, and the points within `tol` of the reference
--- surface are kept (a circle or a point gives its one point); every point lies midway
--- between the two surfaces after the move (on both, to round-off) and has the pair's depth.
--- Ids as the header says, those a single pair gets from the same features: clipped points'
--- from the faces, a circle over face i 2 * i, over vertex v of a shape 2 * v + 1, two
--- circles 0, two rounded corners side 2's.
---@param A strike.Shape
---@param B strike.Shape
---@param tx number
---@param ty number
---@param nx number
---@param ny number
---@param depth number
---@param face integer
---@param ia integer
---@param ib integer
---@param tol number
---@param out table
---@param k0 integer
---@return integer count
function contact.pushed(A, B, tx, ty, nx, ny, depth, face, ia, ib, tol, out, k0)
  if face ~= 0 then
    local Ref, r, rox, roy, I, iox, ioy, side = A, face, 0, 0, B, tx, ty, 0
    if face < 0 then Ref, r, rox, roy, I, iox, ioy, side = B, -face, tx, ty, A, 0, 0, 1 end
    local px, py = corePoint(I)
    if not px then
      local k = STRIDE * r + BASE
      return clipFaces(out, k0, Ref, r, rox, roy, I, (alignedFace(I, -Ref[k + NX], -Ref[k + NY])), iox, ioy, side,
        false, tol, depth)
    end
    -- a circle (or a point) on the face: its centre moved to midway between the surfaces
    local k = STRIDE * r + BASE
    local rnx, rny = Ref[k + NX], Ref[k + NY]
    px, py = px + iox, py + ioy
    local sep = rnx * (px - Ref[k] - rox) + rny * (py - Ref[k + VY] - roy)
    local h = (Ref[R] - I[R] - sep) / 2
    setPoint(out, k0 + 1, px + rnx * h, py + rny * h, depth, 2 * r)
    return 1
  end
  -- two rounded corners (or circles): midway between A's surface and B's along the normal
  local ax, ay = coreVertex(A, ia)
  local bx, by = coreVertex(B, ib)
  local ra, rb = A[R], B[R]
  local id
  if not A[COUNT] then
    id = B[COUNT] and 2 * ib + 1 or 0
  elseif not B[COUNT] then
    id = 2 * ia + 1
  else
    id = ((2 * 65536 + ia) * 65536 + ib) * 4
  end
  setPoint(out, k0 + 1, (ax + nx * ra + bx + tx - nx * rb) / 2, (ay + ny * ra + by + ty - ny * rb) / 2, depth, id)
  return 1
end

--- No contact (for pairs of kinds that never collide).
---@return integer count always 0
function contact.none() return 0 end

return contact
