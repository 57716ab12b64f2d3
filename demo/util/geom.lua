--- Small geometry helpers shared by the LÖVE painter and the probe model. Pure Lua.
local geom = {}

local sqrt = math.sqrt

--- The two short strokes of an arrow head at (x2, y2), for an arrow from (x1, y1).
---@return number ax, number ay, number bx, number by the far ends of the two strokes
function geom.arrowHead(x1, y1, x2, y2, size)
  size = size or 7
  local dx, dy = x2 - x1, y2 - y1
  local l = sqrt(dx * dx + dy * dy)
  if l == 0 then return x2, y2, x2, y2 end
  dx, dy = dx / l * size, dy / l * size
  -- back along the arrow, and half as far to each side
  return x2 - dx - dy * 0.5, y2 - dy + dx * 0.5, x2 - dx + dy * 0.5, y2 - dy - dx * 0.5
end

--- Distance from (px, py) to the segment (x1, y1)-(x2, y2).
---@return number
function geom.segmentDistance(px, py, x1, y1, x2, y2)
  local dx, dy = x2 - x1, y2 - y1
  local l2 = dx * dx + dy * dy
  local t = 0
  if l2 > 0 then
    t = ((px - x1) * dx + (py - y1) * dy) / l2
    if t < 0 then t = 0 elseif t > 1 then t = 1 end
  end
  local ex, ey = x1 + dx * t - px, y1 + dy * t - py
  return sqrt(ex * ex + ey * ey)
end

--- Distance from (px, py) to the segment, or to the nearest of a body's leaves, for picking
--- with the mouse: 0 inside a shape with area, else the distance to its nearest boundary
--- (edges have no inside, so this is how an edge is grabbed).
---@param body table a strike shape or collider
---@return number
function geom.pickDistance(body, px, py)
  local best = math.huge
  local function leaf(s)
    local d
    if s:containsPoint(px, py) then
      d = 0
    elseif s:getKind() == 'circle' then
      local x, y = s:getCentroid()
      d = sqrt((px - x) ^ 2 + (py - y) ^ 2) - s:getRadius()
    else
      d = math.huge
      for _, x1, y1, x2, y2 in s:ipairs() do
        local e = geom.segmentDistance(px, py, x1, y1, x2, y2)
        if e < d then d = e end
      end
    end
    if d < best then best = d end
  end
  if body.getShapeCount then
    for s in body:elems() do leaf(s) end
  else
    leaf(body)
  end
  return best
end

return geom
