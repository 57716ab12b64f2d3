--- A concave (simple) polygon, split into few convex pieces.
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(ROOT .. '.colliders.Collider')
local ConvexPolygon = require(ROOT .. '.shapes.ConvexPolygon')
local decompose = require(ROOT .. '.geometry.decompose')
local check = require(ROOT .. '.check')

---@class strike.Concave : strike.Collider
local Concave = Collider:extend()
Concave.name = 'Concave'

--- A collider for the simple polygon x1, y1, x2, y2, ... (or one table {x1, y1, ...}), in
--- either winding. It holds convex pieces that tile the outline exactly (triangulation by
--- monotone partition, then Hertel-Mehlhorn merging; O(n log n) for n vertices).
--- Self-intersecting or degenerate outlines are an error.
---@param ... number|number[]
function Concave:new(...)
  local xs, ys, n = check.coordinates('strike.Concave', ...)
  local pieces, err = decompose.decompose(xs, ys, n)
  if not pieces then check.fail('strike.Concave: ' .. err) end
  Collider.new(self)
  for i = 1, #pieces do self:add(ConvexPolygon(pieces[i])) end
end

return Concave
