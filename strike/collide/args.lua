--- Argument checks of the collision entry points (S.AT, S.triking, S.ite, S.ettle, ...):
--- what counts as a shape and a collider, and the errors for what does not. The hot
--- paths inline the tests (a shape is a table with a pose stamp `_pose` and a registered
--- kind; a collider one with its own leaf cache field `_single`, see colliders/Collider.lua)
--- and call these only to raise the error, at the caller's line.
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local check = require(ROOT .. '.check')
local Shape = require(ROOT .. '.base.Shape')
local dispatch = require(ROOT .. '.collide.dispatch')
local pair, kinds = dispatch.pair, dispatch.kind
local reserved = require(ROOT .. '.reserved')
local classType = reserved.classType

local describe, what, fail = check.describe, check.what, check.fail

local args = {}

--- True for a strike shape (`v` a table).
---@param v table
---@return boolean
function args.isShape(v) return v._pose ~= nil and pair[v._kind] ~= nil end

--- True for a strike collider (`v` a table).
---@param v table
---@return boolean
function args.isCollider(v) return v._single ~= nil end


--- Raise the error for argument `i` of `fname`, which had to be a strike shape and is `v`:
--- a shape with a field of strike's the game changed (naming it), a collider, an instance of
--- an incomplete shape class (naming what it lacks), a shape that was never built, or
--- anything else.
---@param fname string
---@param i integer
---@param v any
function args.badShape(fname, i, v)
  local t = classType(v)
  if t == 'collider' then
    fail(('%s: argument %d must be a shape, got a collider (use S.triking for colliders)'):format(fname, i))
  end
  if t == 'shape' then
    reserved.check(fname, 'argument ' .. i, v)
    -- an instance of a shape class: name what its class lacks, or say it was never built
    local mt = getmetatable(v)
    Shape.checkClass(mt, ('%s: argument %d (a %s)'):format(fname, i, tostring(mt.name)))
    if v._pose == nil then
      fail(('%s: argument %d (a %s) was not built by a strike shape constructor (its new must call'
        .. ' the parent\'s: Class.super.new(self, ...))'):format(fname, i, tostring(mt.name)))
    end
  end
  fail(('%s: argument %d must be a strike shape, got %s'):format(fname, i, describe(v)))
end

--- Raise the error for argument `i` of `fname`, which had to be a collider or a shape: a body
--- with a field of strike's the game changed (naming it), one never built, or anything else.
---@param fname string
---@param i integer
---@param v any
function args.badBody(fname, i, v)
  local t = classType(v)
  if t == 'shape' then args.badShape(fname, i, v) end
  if t == 'collider' then
    reserved.check(fname, 'argument ' .. i, v)
    if rawget(v, '_single') == nil then
      fail(('%s: argument %d (a %s) was not built by a strike collider constructor (its new must call the'
        .. ' parent\'s: Class.super.new(self, ...))'):format(fname, i, tostring(getmetatable(v).name)))
    end
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

--- Raise the error for two shapes `a` and `b` whose pair of kinds no narrow phase is
--- registered for: a `_kind` the game changed (named as such: `body1` and `body2`, when given,
--- are the arguments that are or hold them; else the message says "a shape"), or a pair of
--- real kinds without a kernel.
---@param fname string
---@param a table
---@param b table
---@param body1 table|nil
---@param body2 table|nil
function args.noKernel(fname, a, b, body1, body2)
  if kinds[a._kind] == nil then reserved.badKind(fname, a, body1 and 'argument 1', body1) end
  if kinds[b._kind] == nil then reserved.badKind(fname, b, body2 and 'argument 2', body2) end
  fail(('%s: no narrow phase for kinds %s and %s'):format(fname, tostring(a._kind), tostring(b._kind)))
end

return args
