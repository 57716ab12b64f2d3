--- Contact manifolds: where two colliding convex shapes touch, from their MTV.
---
--- Polygons (and edges) use reference-face clipping (Catto, "Contact Manifolds", GDC 2007;
--- the same scheme as Box2D's b2ClipPolygons and dyn4j's clipping solver): the reference
--- face is the face, of either shape, most closely aligned with the contact normal (the
--- first shape's wins unless the second's is better by 1e-6 in cosine, so that resting
--- contacts do not flip between frames); the incident face is the other shape's face most
--- opposed to it; the incident face is clipped to the reference face's side planes and
--- the points behind the reference face are kept. Circles give one point.
---
--- Every point lies midway between the two surfaces: half its depth in front of the
--- incident feature, half behind the reference one. Its id names the features that made
--- it, so it stays the same while the same features touch:
---   id = ((side * 65536 + referenceFace) * 65536 + incidentFace) * 4 + corner
--- side 0 when the reference face is the first shape's, 1 when the second's; corner 0 or 1
--- for an incident vertex kept as it is, 2 or 3 for a point cut by the reference face's
--- first or second side plane. A circle's point has id = 2 * face (centre over that face of
--- the polygon) or 2 * vertex + 1 (over that vertex), and 0 for two circles.
local contact = {}

local sqrt, huge = math.sqrt, math.huge

-- Write point k of `out`, reusing its table (a second point's table is kept in
-- out._spare while the manifold has one point, so that #out is always the count).
local function setPoint(out, k, x, y, depth, id)
  local p = out[k] or (k == 2 and out._spare)
  if not p then p = { x = 0, y = 0, depth = 0, id = 0 } end
  out[k] = p
  p.x, p.y, p.depth, p.id = x, y, depth, id
end

-- The face of polygon P whose normal is most aligned with (nx, ny), and that cosine.
local function alignedFace(P, nx, ny)
  local best, bi = -huge, 1
  for i = 1, P._n do
    local k = 5 * i
    local d = P[k + 2] * nx + P[k + 3] * ny
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

-- Clip and keep, with R the reference polygon (face r) and I the incident one (face f).
-- Returns the number of points written. `side` is 0 or 1 (see the header).
local function clipFaces(out, R, r, I, f, side)
  local rk = 5 * r
  local rl = r < R._n and rk + 5 or 5
  local v1x, v1y, v2x, v2y = R[rk], R[rk + 1], R[rl], R[rl + 1]
  local nx, ny = R[rk + 2], R[rk + 3]
  local tx, ty = v2x - v1x, v2y - v1y
  local len = sqrt(tx * tx + ty * ty)
  tx, ty = tx / len, ty / len
  local ik = 5 * f
  local il = f < I._n and ik + 5 or 5
  local ax, ay, bx, by = I[ik], I[ik + 1], I[il], I[il + 1]
  local ca, cb = 0, 1 -- which corner each end is (see the header)
  -- side plane 1: dot(t, p - v1) >= 0
  local lo = tx * v1x + ty * v1y
  ax, ay, bx, by, ca, cb = clip(ax, ay, bx, by, ca, cb, tx * ax + ty * ay - lo, tx * bx + ty * by - lo, 2)
  if not ax then return 0 end
  -- side plane 2: dot(t, p - v2) <= 0
  local hi = tx * v2x + ty * v2y
  ax, ay, bx, by, ca, cb = clip(ax, ay, bx, by, ca, cb, hi - (tx * ax + ty * ay), hi - (tx * bx + ty * by), 3)
  if not ax then return 0 end
  -- keep what is behind the reference face
  local off = nx * v1x + ny * v1y
  local base = ((side * 65536 + r) * 65536 + f) * 4
  local k = 0
  local sa = nx * ax + ny * ay - off
  if sa < 0 then
    k = k + 1
    setPoint(out, k, ax - nx * sa / 2, ay - ny * sa / 2, -sa, base + ca)
  end
  local sb = nx * bx + ny * by - off
  if sb < 0 then
    k = k + 1
    setPoint(out, k, bx - nx * sb / 2, by - ny * sb / 2, -sb, base + cb)
  end
  return k
end

-- The feature of polygon P nearest the point (cx, cy) as an id: 2 * face or 2 * vertex + 1.
local function circleFeature(P, cx, cy)
  local n = P._n
  local best, bi = -huge, 1
  for i = 1, n do
    local k = 5 * i
    local s = P[k + 2] * (cx - P[k]) + P[k + 3] * (cy - P[k + 1])
    if s > best then best, bi = s, i end
  end
  local j = bi < n and bi + 1 or 1
  local x1, y1, x2, y2 = P[5 * bi], P[5 * bi + 1], P[5 * j], P[5 * j + 1]
  if (cx - x1) * (x2 - x1) + (cy - y1) * (y2 - y1) <= 0 then return 2 * bi + 1 end
  if (cx - x2) * (x1 - x2) + (cy - y2) * (y1 - y2) <= 0 then return 2 * j + 1 end
  return 2 * bi
end

--- Fill `out` with the contact points of a colliding MTV (see the header), and return
--- the count (0 for a separating MTV).
---@param mtv strike.MTV @param out table
---@return integer
function contact.manifold(mtv, out)
  if mtv.separating or not (mtv.depth > 0) then return 0 end -- luacheck: ignore 581
  local A, B = mtv.colliderShape, mtv.collidedShape
  local nx, ny, depth = mtv.nx, mtv.ny, mtv.depth
  if A._dirty then A:_refresh() end
  if B._dirty then B:_refresh() end
  if A.kind == 'circle' then
    local r = A._r * A._scale
    local id = B.kind == 'circle' and 0 or circleFeature(B, A._x, A._y)
    setPoint(out, 1, A._x + nx * (r - depth / 2), A._y + ny * (r - depth / 2), depth, id)
    return 1
  elseif B.kind == 'circle' then
    local r = B._r * B._scale
    setPoint(out, 1, B._x - nx * (r - depth / 2), B._y - ny * (r - depth / 2), depth, circleFeature(A, B._x, B._y))
    return 1
  end
  local fa, alignA = alignedFace(A, nx, ny)
  local fb, alignB = alignedFace(B, -nx, -ny)
  local k
  if alignB > alignA + 1e-6 then
    k = clipFaces(out, B, fb, A, (alignedFace(A, -B[5 * fb + 2], -B[5 * fb + 3])), 1)
  else
    k = clipFaces(out, A, fa, B, (alignedFace(B, -A[5 * fa + 2], -A[5 * fa + 3])), 0)
  end
  if k == 0 then
    -- Round-off left nothing behind the face: report the deepest vertex of B.
    local best, bj = huge, 1
    for j = 1, B._n do
      local p = nx * B[5 * j] + ny * B[5 * j + 1]
      if p < best then best, bj = p, j end
    end
    setPoint(out, 1, B[5 * bj] + nx * depth / 2, B[5 * bj + 1] + ny * depth / 2, depth, bj)
    k = 1
  end
  return k
end

return contact
