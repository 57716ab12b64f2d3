--- Scalar 2D vector helpers: numbers in, numbers out, never a table.
local sqrt = math.sqrt
local vec = {}

---@param x1 number @param y1 number @param x2 number @param y2 number
---@return number
function vec.dot(x1, y1, x2, y2) return x1 * x2 + y1 * y2 end

--- z of the 3D cross product (positive when (x2,y2) is counter-clockwise from (x1,y1) in y-up axes).
---@return number
function vec.cross(x1, y1, x2, y2) return x1 * y2 - y1 * x2 end

---@return number
function vec.len(x, y) return sqrt(x * x + y * y) end

---@return number
function vec.len2(x, y) return x * x + y * y end

---@return number
function vec.dist(x1, y1, x2, y2)
  local dx, dy = x2 - x1, y2 - y1
  return sqrt(dx * dx + dy * dy)
end

--- Unit vector and the original length; (0, 0, 0) for the zero vector.
---@return number nx, number ny, number len
function vec.normalize(x, y)
  local l = sqrt(x * x + y * y)
  if l == 0 then return 0, 0, 0 end
  return x / l, y / l, l
end

--- Rotate (x, y) by the angle whose cosine and sine are c and s.
---@return number, number
function vec.rotate(c, s, x, y) return c * x - s * y, s * x + c * y end

--- Signed area (shoelace, positive for counter-clockwise in y-up axes) and area centroid
--- of the polygon given by flat arrays xs, ys of length n. Coordinates are taken relative
--- to the first vertex to limit round-off.
---@param xs number[] @param ys number[] @param n integer
---@return number area, number cx, number cy
function vec.polygonAreaCentroid(xs, ys, n)
  local ox, oy = xs[1], ys[1]
  local a2, cx, cy = 0, 0, 0
  for i = 2, n - 1 do
    local x1, y1 = xs[i] - ox, ys[i] - oy
    local x2, y2 = xs[i + 1] - ox, ys[i + 1] - oy
    local c = x1 * y2 - x2 * y1
    a2 = a2 + c
    cx = cx + (x1 + x2) * c
    cy = cy + (y1 + y2) * c
  end
  if a2 == 0 then return 0, ox, oy end
  return a2 / 2, ox + cx / (3 * a2), oy + cy / (3 * a2)
end

return vec
