--- A concave (simple) polygon, split into few convex pieces.
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(ROOT .. '.colliders.Collider')
local ConvexPolygon = require(ROOT .. '.shapes.ConvexPolygon')
local decompose = require(ROOT .. '.geometry.decompose')
local check = require(ROOT .. '.check')
local badSelf, type = check.badSelf, type

---@class strike.Concave : strike.Collider
local Concave = Collider:extend()
Concave.name = 'Concave'

--- A collider for the simple polygon x1, y1, x2, y2, ... (or one table {x1, y1, ...}), in
--- either winding. It holds convex pieces that tile the outline exactly (triangulation by
--- monotone partition, then Hertel-Mehlhorn merging; O(n log n) for n vertices).
--- Self-intersecting or degenerate outlines are an error.
---@param ... number|number[]
function Concave:new(...)
  if type(self) ~= 'table' or getmetatable(self) == nil then badSelf(self, 'strike.Concave:new') end
  local xs, ys, n = check.coordinates('strike.Concave', ...)
  local pieces, err = decompose.decompose(xs, ys, n)
  if not pieces then check.fail('strike.Concave: ' .. err) end
  Collider.new(self)
  for i = 1, #pieces do
    -- (built as ConvexPolygon(pieces[i]) would be, but an error, such as a piece outside
    -- strike's limits on lengths, names strike.Concave)
    local piece = setmetatable({ _fname = 'strike.Concave' }, ConvexPolygon)
    piece:new(pieces[i])
    piece._fname = nil
    self:add(piece)
  end
end

return Concave
