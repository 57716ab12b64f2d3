--- Argument checks of the collision entry points (S.AT, S.triking, S.ite, S.ettle, ...):
--- what counts as a shape and a collider, and the errors for what does not. The hot
--- paths inline the tests (a shape is a table with a pose stamp `_pose` and a registered
--- kind; a collider one with its own leaf cache field `_single`, see colliders/Collider.lua)
--- and call these only to raise the error, at the caller's line.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local check = require(ROOT .. '.check')
local Shape = require(ROOT .. '.base.Shape')
local pair = require(ROOT .. '.collide.dispatch').pair

local describe, what, fail = check.describe, check.what, check.fail

local args = {}

--- True for a strike shape (`v` a table).
---@param v table
---@return boolean
function args.isShape(v) return v._pose ~= nil and pair[v.kind] ~= nil end

--- True for a strike collider (`v` a table).
---@param v table
---@return boolean
function args.isCollider(v) return v._single ~= nil end


--- Raise the error for argument `i` of `fname`, which had to be a strike shape and is `v`:
--- a collider, an instance of an incomplete shape class (naming what it lacks), a shape
--- that was never built, or anything else.
---@param fname string
---@param i integer
---@param v any
function args.badShape(fname, i, v)
  if type(v) == 'table' then
    if v.type == 'collider' then
      fail(('%s: argument %d must be a shape, got a collider (use S.triking for colliders)'):format(fname, i))
    end
    local mt = getmetatable(v)
    if type(mt) == 'table' and mt.type == 'shape' then
      -- an instance of a shape class: name what its class lacks, or say it was never built
      Shape.checkClass(mt, ('%s: argument %d (a %s)'):format(fname, i, tostring(v.name)))
      if v._pose == nil then
        fail(('%s: argument %d (a %s) was not built by a strike shape constructor (its new must call'
          .. ' the parent\'s: Class.super.new(self, ...))'):format(fname, i, tostring(v.name)))
      end
    end
  end
  fail(('%s: argument %d must be a strike shape, got %s'):format(fname, i, describe(v)))
end

--- Raise the error for argument `i` of `fname`, which had to be a collider or a shape.
---@param fname string
---@param i integer
---@param v any
function args.badBody(fname, i, v)
  if type(v) == 'table' and v.type == 'shape' then args.badShape(fname, i, v) end
  if type(v) == 'table' and v.type == 'collider' and getmetatable(v) ~= nil and v._single == nil then
    fail(('%s: argument %d (a %s) was not built by a strike collider constructor (its new must call the'
      .. ' parent\'s: Class.super.new(self, ...))'):format(fname, i, tostring(v.name)))
  end
  fail(('%s: argument %d must be a strike collider or shape, got %s'):format(fname, i, describe(v)))
end

--- Raise the error for an `out` argument (number `i` of `fname`) that is not an MTV-shaped
--- table: not a table, or one of strike's other objects.
---@param fname string
---@param out any
---@param i integer
function args.badOut(fname, out, i)
  fail(('%s: argument %d (out) must be a table such as S.MTV(), got %s'):format(fname, i, what(out)))
end

--- Raise the error for a pair of shape kinds that no narrow phase is registered for.
---@param fname string
---@param ka string
---@param kb string
function args.noKernel(fname, ka, kb)
  fail(('%s: no narrow phase for kinds %s and %s'):format(fname, tostring(ka), tostring(kb)))
end

return args
