--- An independent geometry oracle for the ray property specs, built on
--- spec/property/brute.lua (shape descriptions from brute.of: public accessors only).
--- Nothing here calls strike's ray code, normals or containment.
local brute = require('spec.property.brute')

local rb = {}

local sqrt, huge, abs = math.sqrt, math.huge, math.abs

--- Distance from (x, y) to the boundary of the description D (circle, polygon, segment).
function rb.boundaryDist(D, x, y)
  if D.circle then
    local dx, dy = x - D.x, y - D.y
    return abs(sqrt(dx * dx + dy * dy) - D.r)
  end
  return brute.boundaryDist(D, x, y)
end

--- True when (x, y) is strictly inside D (a segment has no inside).
function rb.inside(D, x, y)
  if D.circle then
    local dx, dy = x - D.x, y - D.y
    return dx * dx + dy * dy < D.r * D.r
  end
  return brute.insideConvex(D, x, y)
end

--- The centre used for "pointing away" (circle centre, vertex mean) and the radius of a
--- circle about it that holds D.
function rb.boundingCircle(D)
  if D.circle then return D.x, D.y, D.r end
  local cx, cy = 0, 0
  for i = 1, D.n do cx, cy = cx + D.xs[i], cy + D.ys[i] end
  cx, cy = cx / D.n, cy / D.n
  local r = 0
  for i = 1, D.n do
    local dx, dy = D.xs[i] - cx, D.ys[i] - cy
    r = math.max(r, sqrt(dx * dx + dy * dy))
  end
  return cx, cy, r
end

--- A point well inside D: a convex combination of the vertices with every weight at
--- least 1/(4n) (polygons), a point of the segment's middle 80% (segments), a point within
--- 0.8 r of the centre (circles).
function rb.interiorPoint(D, rng)
  if D.circle then
    local a, k = rng:range(0, 2 * math.pi), 0.8 * D.r * sqrt(rng:next())
    return D.x + k * math.cos(a), D.y + k * math.sin(a)
  end
  if D.n == 2 then
    local s = rng:range(0.1, 0.9)
    return D.xs[1] + s * (D.xs[2] - D.xs[1]), D.ys[1] + s * (D.ys[2] - D.ys[1])
  end
  local w, sum = {}, 0
  for i = 1, D.n do
    w[i] = 0.25 + rng:next()
    sum = sum + w[i]
  end
  local x, y = 0, 0
  for i = 1, D.n do x, y = x + w[i] / sum * D.xs[i], y + w[i] / sum * D.ys[i] end
  return x, y
end

--- Brute-force hits of the ray (origin ox, oy; unit direction ux, uy) on the boundary
--- segments of D, by a route of its own: for each boundary segment a-b, the signed area
--- f(t) = cross(b - a, o + t u - a) is linear in t, and its root is accepted when that
--- point projects into the segment (within a relative slack). Returns the least and the
--- largest t >= 0 found (nil when none), for a transversal ray. Circles: the textbook
--- quadratic.
function rb.hitRange(D, ox, oy, ux, uy)
  local lo, hi = huge, -huge
  local function take(t)
    if t >= 0 then
      if t < lo then lo = t end
      if t > hi then hi = t end
    end
  end
  if D.circle then
    local mx, my = ox - D.x, oy - D.y
    local b = mx * ux + my * uy
    local c = mx * mx + my * my - D.r * D.r
    local disc = b * b - c
    if disc < 0 then return nil end
    take(-b - sqrt(disc))
    take(-b + sqrt(disc))
  else
    local xs, ys, n = D.xs, D.ys, D.n
    local m = n == 2 and 1 or n
    for i = 1, m do
      local j = i < n and i + 1 or 1
      local ax, ay, bx, by = xs[i], ys[i], xs[j], ys[j]
      local f0 = brute.cross(ax, ay, bx, by, ox, oy)
      local f1 = brute.cross(ax, ay, bx, by, ox + ux, oy + uy)
      if f1 ~= f0 then
        local t = -f0 / (f1 - f0)
        local px, py = ox + t * ux, oy + t * uy
        local ex, ey = bx - ax, by - ay
        local s = ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey)
        if s >= -1e-9 and s <= 1 + 1e-9 then take(t) end
      end
    end
  end
  if lo == huge then return nil end
  return lo, hi
end

return rb
