--- Measures of polygons given as flat coordinate arrays.
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

return polygon
