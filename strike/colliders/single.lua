--- Single-shape colliders: S.trikers.<ShapeName>(...) is a Collider class holding exactly
--- one S.hapes.<ShapeName>(...) built from the same arguments. The shape class is looked up
--- in the registry at construction, so re-registering a shape name is followed.
local ROOT = (...):match('^(.-)%.colliders%.[^%.]+$')
local Collider = require(ROOT .. '.colliders.Collider')
local Shape = require(ROOT .. '.base.Shape')
local check = require(ROOT .. '.check')
local layout = require(ROOT .. '.base.layout')

--- Make the single-shape collider class for the shape registered as `name`.
---@param shapes table the S.hapes registry
---@param name string
---@return table
return function(shapes, name)
  local Single = Collider:extend()
  Single.name = name
  function Single:new(...)
    if type(self) ~= 'table' or getmetatable(self) == nil then
      check.badSelf(self, 'strike.trikers.' .. name .. ':new')
    end
    local ShapeClass = shapes[name]
    if not ShapeClass then check.fail(('strike.trikers.%s: S.hapes.%s is no longer registered'):format(name, name)) end
    Shape._forCollider(true) -- (room for the fields of a shape the collider keeps: Shape._slots)
    local shape = ShapeClass(...)
    Shape._forCollider(false) -- (in case the class made its instance without Shape._slots)
    Collider._newSingle(self, shape, ShapeClass)
    self[layout.CANGLE] = shape[layout.ANGLE]
  end
  return Single
end
