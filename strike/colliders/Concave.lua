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
--- either winding. It holds convex pieces that tile the outline exactly (ear clipping,
--- then Hertel-Mehlhorn merging). Self-intersecting or degenerate outlines are an error.
---@param ... number|number[]
function Concave:new(...)
  local args, count = ..., select('#', ...)
  if type(args) == 'table' then count = #args else args = { ... } end
  if count % 2 ~= 0 then
    check.fail(('strike.Concave: expected x, y pairs, got an odd number of values (%d)'):format(count))
  end
  local xs, ys, n = {}, {}, count / 2
  for i = 1, n do
    local x, y = args[2 * i - 1], args[2 * i]
    if not check.finite(x) then
      check.fail(('strike.Concave: x%d must be a finite number, got %s'):format(i, check.describe(x)))
    end
    if not check.finite(y) then
      check.fail(('strike.Concave: y%d must be a finite number, got %s'):format(i, check.describe(y)))
    end
    xs[i], ys[i] = x, y
  end
  local pieces, err = decompose.decompose(xs, ys, n)
  if not pieces then check.fail('strike.Concave: ' .. err) end
  Collider.new(self)
  for i = 1, #pieces do self:add(ConvexPolygon(pieces[i])) end
end

return Concave
