--- S.hapes and S.trikers: class registries. Built-in classes are registered when strike
--- loads. Any other name is looked up on first use by requiring `<root>.shapes.<Name>` (or
--- `<root>.colliders.<Name>`), so a file dropped into strike/shapes/ or strike/colliders/
--- registers itself; assigning `S.hapes.Name = Class` registers a class from anywhere.
--- Nothing lists directories. Every shape name also gets a single-shape collider class
--- in S.trikers. A name registers once through assignment (later assignments to the same
--- name replace the class without checks, as for any table field).
local ROOT = (...):match('^(.-)%.[^%.]+$')
local Object = require(ROOT .. '.class')
local Shape = require(ROOT .. '.base.Shape')
local Collider = require(ROOT .. '.colliders.Collider')
local single = require(ROOT .. '.colliders.single')
local check = require(ROOT .. '.check')

local registry = {}

local function isClassOf(v, Base)
  return type(v) == 'table' and v ~= Base and rawget(v, '__index') == v and Object.is(v, Base)
end

-- require(mod) if that module exists: nil when it does not, an error when it fails.
local function tryRequire(mod)
  local ok, res = pcall(require, mod)
  if ok then return res end
  if type(res) == 'string' and res:find("module '" .. mod .. "' not found", 1, true) then return nil end
  error(res, 0)
end

local function validName(name)
  return type(name) == 'string' and name:match('^[%a_][%w_]*$') ~= nil
end

--- Build the two registries.
---@return table hapes, table trikers
function registry.new()
  local shapes, colliders = {}, {}
  local missingShape, missingCollider = {}, {}

  local function nameClass(cls, name)
    if rawget(cls, 'name') == nil then rawset(cls, 'name', name) end
  end

  setmetatable(shapes, {
    __index = function(t, name)
      if not validName(name) or missingShape[name] then return nil end
      local cls = tryRequire(ROOT .. '.shapes.' .. name)
      if cls == nil then missingShape[name] = true return nil end
      if not isClassOf(cls, Shape) then
        check.fail(('strike: shapes/%s.lua must return a class extending a strike shape, got %s')
          :format(name, check.describe(cls)))
      end
      Shape.checkClass(cls, ('strike: the class in shapes/%s.lua'):format(name))
      nameClass(cls, name)
      rawset(t, name, cls)
      return cls
    end,
    __newindex = function(t, name, cls)
      if not validName(name) then
        check.fail(('strike: S.hapes names must be identifiers, got %s'):format(check.describe(name)))
      end
      if not isClassOf(cls, Shape) then
        check.fail(('strike: S.hapes.%s must be a class extending a strike shape (e.g. '
          .. 'S.hapes.ConvexPolygon:extend()), got %s'):format(name, check.describe(cls)))
      end
      Shape.checkClass(cls, ('strike: S.hapes.%s'):format(name))
      nameClass(cls, name)
      missingShape[name], missingCollider[name] = nil, nil
      rawset(t, name, cls)
    end,
  })

  setmetatable(colliders, {
    __index = function(t, name)
      if not validName(name) or missingCollider[name] then return nil end
      local cls = tryRequire(ROOT .. '.colliders.' .. name)
      if cls ~= nil then
        if not isClassOf(cls, Collider) then
          check.fail(('strike: colliders/%s.lua must return a class extending S.trikers.Collider, got %s')
            :format(name, check.describe(cls)))
        end
        nameClass(cls, name)
      else
        if not shapes[name] then missingCollider[name] = true return nil end
        cls = single(shapes, name)
      end
      rawset(t, name, cls)
      return cls
    end,
    __newindex = function(t, name, cls)
      if not validName(name) then
        check.fail(('strike: S.trikers names must be identifiers, got %s'):format(check.describe(name)))
      end
      if not isClassOf(cls, Collider) then
        check.fail(('strike: S.trikers.%s must be a class extending S.trikers.Collider, got %s')
          :format(name, check.describe(cls)))
      end
      nameClass(cls, name)
      missingCollider[name] = nil
      rawset(t, name, cls)
    end,
  })

  rawset(colliders, 'Collider', Collider)
  return shapes, colliders
end

return registry
