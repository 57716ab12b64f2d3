--- Measures of polygons given as flat coordinate arrays.
local ROOT = (...):match('^(.-)%.geometry%.[^%.]+$')
local atan2 = require(ROOT .. '.compat').atan2
local sqrt, sin, cos, pi = math.sqrt, math.sin, math.cos, math.pi

local polygon = {}

--- Signed area (shoelace: positive for positive winding) and area centroid of the polygon
--- xs, ys (count n). Coordinates are taken relative to the first vertex to limit round-off.
---@param xs number[]
---@param ys number[]
---@param n integer
---@return number area, number cx, number cy
function polygon.areaCentroid(xs, ys, n)
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

--- Area and centroid of the polygon xs, ys (count n, positive winding, area and centroid
--- cx, cy as areaCentroid gives them) rounded by r > 0: every point within r of it. The
--- rounded shape is the polygon, a strip r wide along each edge (a rectangle, centroid at
--- the edge's midpoint plus r / 2 along its outward normal) and a circular sector at each
--- vertex spanning the turn theta between its two edges' normals (area r^2 theta / 2,
--- centroid 4 r sin(theta / 2) / (3 theta) from the vertex along the bisector); the turns
--- add up to 2 pi, so the area is A + r * perimeter + pi r^2 (the Steiner formula). A
--- segment (n = 2, both edges) and a point (n = 2, both vertices equal) work alike.
---@param xs number[]
---@param ys number[]
---@param n integer
---@param area number
---@param cx number
---@param cy number
---@param r number
---@return number area, number cx, number cy
function polygon.rounded(xs, ys, n, area, cx, cy, r)
  local total, mx, my = area, area * cx, area * cy
  for i = 1, n do
    local j = i < n and i + 1 or 1
    local h = i > 1 and i - 1 or n
    local ex, ey = xs[j] - xs[i], ys[j] - ys[i]
    local len = sqrt(ex * ex + ey * ey)
    -- the strip along edge i (none for a point's zero-length edges)
    if len > 0 then
      local nx, ny = ey / len, -ex / len
      local a = r * len
      total = total + a
      mx = mx + a * ((xs[i] + xs[j]) / 2 + nx * r / 2)
      my = my + a * ((ys[i] + ys[j]) / 2 + ny * r / 2)
    end
    -- the sector at vertex i, from edge h's normal to edge i's
    local px, py = xs[i] - xs[h], ys[i] - ys[h]
    local theta
    if (px == 0 and py == 0) or len == 0 then
      theta = pi -- (a point: two half discs, one at each of its two vertices)
    else
      theta = atan2(px * ey - py * ex, px * ex + py * ey) -- the turn from edge h to edge i
      if theta < 0 then theta = theta + 2 * pi end
      if n == 2 then theta = pi end -- (a segment: a half disc at each end)
    end
    if theta > 0 then
      local a = r * r * theta / 2
      local bx, by -- the bisector of the two normals
      if len > 0 then
        local ux, uy = ex / len, ey / len -- (edge i's direction turned back by theta / 2)
        local c, s = cos(-theta / 2), sin(-theta / 2)
        local dx, dy = ux * c - uy * s, ux * s + uy * c
        bx, by = dy, -dx
      else
        bx, by = 0, 0 -- (a point's sectors balance about it)
      end
      local d = 4 * r * sin(theta / 2) / (3 * theta)
      total = total + a
      mx = mx + a * (xs[i] + bx * d)
      my = my + a * (ys[i] + by * d)
    end
  end
  return total, mx / total, my / total
end

return polygon
