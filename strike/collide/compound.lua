--- Collision between two bodies (colliders, nested to any depth, or bare shapes): the pair
--- loop over their leaf shapes. It is S.triking itself (it checks its arguments, with the
--- reads the work needs anyway, and names S.triking in its errors), and anything else that
--- tests whole bodies calls it too.
---
--- The answer is the deepest MTV over all pairs of leaves whose bounds meet, or false when
--- no pair collides; bodies under one root collider never collide. It reads a collider's
--- leaf list through the cache protocol of colliders/Collider.lua (`_single`: the only
--- leaf, valid while the list is).
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local MTV = require(ROOT .. '.collide.MTV')
local Shape = require(ROOT .. '.base.Shape')
local Collider = require(ROOT .. '.colliders.Collider')
local layout = require(ROOT .. '.base.layout')
local dispatch = require(ROOT .. '.collide.dispatch')
local pair, collideOf = dispatch.pair, dispatch.collide
local args = require(ROOT .. '.collide.args')

local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local min, max = math.min, math.max
local root, leafList = Shape._rootOf, Collider._leafList
local badBody, badOut = args.badBody, args.badOut
local FNAME = 'strike.triking'

local compound = {}

-- Scratch state: two MTVs swapped as the best one changes, and one-slot leaf lists for
-- bare shapes.
local tmpA, tmpB = MTV(), MTV()
local one1, one2 = {}, {}

-- Fill the fields of `out` that name the bodies and the poses it was computed for (S.AT
-- and the one-leaf path below write the same fields inline).
local function stamp(out, r1, r2)
  out.collider, out.collided = r1, r2
  out._poseA, out._poseB = out.colliderShape._pose, out.collidedShape._pose
  return out
end

--- The deepest MTV between the leaves of two bodies (see the header), filled into `out`
--- when given (its contents are unspecified after false), or false.
---@param body1 strike.Collider|strike.Shape
---@param body2 strike.Collider|strike.Shape
---@param out strike.MTV|nil
---@return strike.MTV|false
function compound.collide(body1, body2, out)
  if type(body1) ~= 'table' then badBody(FNAME, 1, body1) end
  if type(body2) ~= 'table' then badBody(FNAME, 2, body2) end
  -- Each body's only leaf, when it has one (a collider's `_single`, false when it has
  -- several or its list is stale; a bare shape is its own), which also tells a collider
  -- (its own field) from a shape (a pose stamp and a registered kind) from anything else.
  local s1, s2 = body1._single, body2._single
  if s1 == nil then
    if body1._pose == nil or not pair[body1.kind] then badBody(FNAME, 1, body1) end
    s1 = body1
  end
  if s2 == nil then
    if body2._pose == nil or not pair[body2.kind] then badBody(FNAME, 2, body2) end
    s2 = body2
  end
  if out ~= nil and (type(out) ~= 'table' or (out.type ~= 'mtv' and out.type ~= nil)) then badOut(FNAME, out, 3) end
  local r1 = body1.parent and root(body1) or body1
  local r2 = body2.parent and root(body2) or body2
  if r1 == r2 then return false end -- every leaf pair would share a root
  if s1 and s2 then
    -- One leaf each, the common case: straight-line code (LuaJIT traces one-trip loops
    -- badly), tested into the caller's `out` when there is one.
    if s1._dirty then s1:_refresh() end
    if s2._dirty then s2:_refresh() end
    if s1[MAXX] < s2[MINX] or s2[MAXX] < s1[MINX] or s1[MAXY] < s2[MINY] or s2[MAXY] < s1[MINY] then
      return false -- the bounds do not even meet
    end
    local collide = collideOf[s1.kind][s2.kind]
    if not collide then args.noKernel(FNAME, s1.kind, s2.kind) end
    local m = collide(s1, s2, out or tmpA)
    if not (m.depth > 0) then return false end -- luacheck: ignore 581 (NaN reads as no collision)
    if not out then out = MTV._set(MTV(), m) end
    out.collider, out.collided = r1, r2
    out._poseA, out._poseB = s1._pose, s2._pose
    return out
  end
  local l1, n1, l2, n2
  if s1 == body1 then l1, n1 = one1, 1; one1[1] = body1 else l1, n1 = leafList(body1) end
  if s2 == body2 then l2, n2 = one2, 1; one2[1] = body2 else l2, n2 = leafList(body2) end
  -- Test into `tmp`; a deeper result becomes `best` and the other buffer becomes `tmp`.
  -- With an `out` table it is one of the two buffers, so the usual single hit needs no copy.
  local best, tmp, found = tmpA, out or tmpB, false
  local bestDepth = 0
  for i = 1, n1 do
    local a = l1[i]
    if a._dirty then a:_refresh() end
    local ax0, ay0, ax1, ay1 = a[MINX], a[MINY], a[MAXX], a[MAXY]
    local row = collideOf[a.kind]
    for j = 1, n2 do
      local b = l2[j]
      if b._dirty then b:_refresh() end
      -- Bounds meet (closed intervals: an axis-aligned edge or a point has a flat box;
      -- the narrow phase decides touching), as two tests instead of four: fewer trace
      -- exits under LuaJIT.
      if min(ax1, b[MAXX]) >= max(ax0, b[MINX]) and min(ay1, b[MAXY]) >= max(ay0, b[MINY]) then
        local collide = row[b.kind]
        if not collide then args.noKernel(FNAME, a.kind, b.kind) end
        collide(a, b, tmp)
        local d = tmp.depth
        if d > bestDepth then -- (false for NaN and for separating results)
          best, tmp, found, bestDepth = tmp, best, true, d
        end
      end
    end
  end
  one1[1], one2[1] = nil, nil -- (bare shapes are not kept alive by strike)
  if not found then return false end
  if best ~= out then out = MTV._set(out or MTV(), best) end
  return stamp(out, r1, r2)
end

return compound
