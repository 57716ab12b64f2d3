--- Convex hull of a point set (Andrew's monotone chain, A. M. Andrew 1979, "Another
--- efficient algorithm for convex hulls in two dimensions"), dropping duplicate and
--- collinear points, plus the test that tells a convex outline from a concave one.
local hull = {}

local sqrt = math.sqrt

-- Relative tolerance for "collinear": |cross(a - o, b - o)| <= EPS * |a - o| * |b - o|,
-- i.e. the sine of the turn is below EPS. (The two lengths are taken apart: the product of
-- their squares, a fourth power, would overflow or underflow for polygons strike accepts.)
local EPS = 1e-10

-- Left turn o -> a -> b, strictly beyond the tolerance.
local function leftTurn(ox, oy, ax, ay, bx, by)
  local ux, uy, vx, vy = ax - ox, ay - oy, bx - ox, by - oy
  local c = ux * vy - uy * vx
  return c > EPS * sqrt(ux * ux + uy * uy) * sqrt(vx * vx + vy * vy)
end

-- hull.order for many points: table.sort with the total order. (A function of its own: the
-- closure would make LuaJIT close upvalues on every return of hull.order, which it does not
-- compile, and every trace through a small polygon's constructor would abort there.)
local function orderMany(xs, ys, n)
  local idx = {}
  for i = 1, n do idx[i] = i end
  table.sort(idx, function(a, b)
    local xa, xb = xs[a], xs[b]
    if xa ~= xb then return xa < xb end
    local ya, yb = ys[a], ys[b]
    if ya ~= yb then return ya < yb end
    return a < b
  end)
  return idx
end

--- The indices 1..n sorted by x, then y, then index (a total order: the result does not
--- depend on table.sort's choices). The hull's scan order, and decompose's sweep order.
---@param xs number[]
---@param ys number[]
---@param n integer
---@return integer[]
function hull.order(xs, ys, n)
  if n > 16 then return orderMany(xs, ys, n) end
  -- (a few points, a polygon's: insertion sort, the same order without a closure)
  local idx = {}
  for i = 1, n do
    local x, y, j = xs[i], ys[i], i - 1
    while j >= 1 do
      local b = idx[j]
      local xb = xs[b]
      if xb < x or (xb == x and ys[b] <= y) then break end -- (b before i: equal points keep their order)
      idx[j + 1] = b
      j = j - 1
    end
    idx[j + 1] = i
  end
  return idx
end

--- Hull of the points (xs[i], ys[i]), i = 1..n, in positive winding (positive shoelace
--- area), without duplicate or collinear vertices.
---@param xs number[]
---@param ys number[]
---@param n integer
---@return number[] hx, number[] hy, integer count, integer distinct number of distinct input points
function hull.build(xs, ys, n)
  local idx = hull.order(xs, ys, n)
  -- drop exact duplicates
  local px, py, m = {}, {}, 0
  for k = 1, n do
    local i = idx[k]
    if m == 0 or xs[i] ~= px[m] or ys[i] ~= py[m] then
      m = m + 1
      px[m], py[m] = xs[i], ys[i]
    end
  end
  local hx, hy, h = {}, {}, 0
  if m < 3 then
    for i = 1, m do hx[i], hy[i] = px[i], py[i] end
    return hx, hy, m, m
  end
  -- lower chain, then upper chain
  for i = 1, m do
    while h >= 2 and not leftTurn(hx[h - 1], hy[h - 1], hx[h], hy[h], px[i], py[i]) do h = h - 1 end
    h = h + 1
    hx[h], hy[h] = px[i], py[i]
  end
  local lower = h + 1
  for i = m - 1, 1, -1 do
    while h >= lower and not leftTurn(hx[h - 1], hy[h - 1], hx[h], hy[h], px[i], py[i]) do h = h - 1 end
    h = h + 1
    hx[h], hy[h] = px[i], py[i]
  end
  h = h - 1 -- the last point repeats the first
  for i = #hx, h + 1, -1 do hx[i], hy[i] = nil, nil end
  return hx, hy, h, m
end

--- True when (x, y) lies strictly inside the convex polygon hx, hy (count h, positive
--- winding), farther than the collinearity tolerance from every edge.
---@param hx number[]
---@param hy number[]
---@param h integer
---@param x number
---@param y number
---@return boolean
function hull.strictlyInside(hx, hy, h, x, y)
  for i = 1, h do -- (first without the tolerance: a hull vertex is on its own edge, c = 0)
    local j = i < h and i + 1 or 1
    if (hx[j] - hx[i]) * (y - hy[i]) - (hy[j] - hy[i]) * (x - hx[i]) <= 0 then return false end
  end
  for i = 1, h do
    local j = i < h and i + 1 or 1
    local ex, ey = hx[j] - hx[i], hy[j] - hy[i]
    local px, py = x - hx[i], y - hy[i]
    local c = ex * py - ey * px
    if c <= EPS * sqrt(ex * ex + ey * ey) * sqrt(px * px + py * py) then return false end
  end
  return true
end

-- Reverse entries a..b of both lists in place.
local function reverse(hx, hy, a, b)
  while a < b do
    hx[a], hx[b], hy[a], hy[b] = hx[b], hx[a], hy[b], hy[a]
    a, b = a + 1, b - 1
  end
end

--- Rotate the hull in place so that it starts at the vertex equal to (x, y), if any.
---@param hx number[]
---@param hy number[]
---@param h integer
---@param x number
---@param y number
function hull.startAt(hx, hy, h, x, y)
  local s
  for i = 1, h do
    if hx[i] == x and hy[i] == y then s = i break end
  end
  if not s or s == 1 then return end
  -- (in place, by three reversals: 1..s-1, s..h, then the whole)
  reverse(hx, hy, 1, s - 1)
  reverse(hx, hy, s, h)
  reverse(hx, hy, 1, h)
end

return hull
