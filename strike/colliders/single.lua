--- Single-shape colliders: S.trikers.<ShapeName>(...) is a Collider class holding exactly
--- one S.hapes.<ShapeName>(...) built from the same arguments.
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(ROOT .. '.colliders.Collider')

--- Make the single-shape collider class for a shape class.
---@param ShapeClass table @param name string
---@return table
return function(ShapeClass, name)
  local Single = Collider:extend()
  Single.name = name
  Single.shapeClass = ShapeClass
  function Single:new(...)
    Collider.new(self, ShapeClass(...))
    self._angle = self.shapes[1]._angle
  end
  return Single
end
