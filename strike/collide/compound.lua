--- Collision between two bodies (colliders, nested to any depth, or bare shapes): the pair
--- loop over their leaf shapes. It is S.triking itself (it checks its arguments, with the
--- reads the work needs anyway, and names S.triking in its errors), and anything else that
--- tests whole bodies calls it too.
---
--- The answer is the shortest translation of the second body that separates all of its
--- members from all of the first's (the outline rule, collide/outline.lua; for one member
--- each, their MTV), or false when no pair collides; bodies under one root collider never
--- collide. Chain segments are one-sided surfaces, not solids: their pairs keep their own
--- (ghost-free) MTV, and when one is deeper than the solid members' answer, it is the
--- answer. It reads a collider's leaf list through the cache protocol of
--- colliders/Collider.lua (`_single`: the only leaf, valid while the list is).
local ROOT = (...):match('^(.-)%.collide%.[^%.]+$')
local MTV = require(ROOT .. '.collide.MTV')
local Shape = require(ROOT .. '.base.Shape')
local Collider = require(ROOT .. '.colliders.Collider')
local layout = require(ROOT .. '.base.layout')
local DIRTY = layout.DIRTY
local dispatch = require(ROOT .. '.collide.dispatch')
local pair, collideOf, kinds = dispatch.pair, dispatch.collide, dispatch.kind
local args = require(ROOT .. '.collide.args')
local outline = require(ROOT .. '.collide.outline')
local resolve, feature = outline.resolve, outline.feature
local contact = require(ROOT .. '.collide.contact')
local pushed = contact.pushed
local abs = math.abs

local MINX, MINY, MAXX, MAXY = layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local min, max = math.min, math.max
local root, leafList = Shape._rootOf, Collider._leafList
local badBody, badOut = args.badBody, args.badOut
local FNAME = 'strike.triking'

-- Does a leaf take part in the outline rule? Every kind but chain segments.
local function solid(s) return s._kind ~= 'chain' end

local compound = {}

-- Scratch state: two MTVs swapped as the best one changes, and one-slot leaf lists for
-- bare shapes.
local tmpA, tmpB = MTV(), MTV()
local letGo = MTV._letGo
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
    if body1._pose == nil or not pair[body1._kind] then badBody(FNAME, 1, body1) end
    s1 = body1
  end
  if s2 == nil then
    if body2._pose == nil or not pair[body2._kind] then badBody(FNAME, 2, body2) end
    s2 = body2
  end
  if out ~= nil and (type(out) ~= 'table' or (out._type ~= 'mtv' and out._type ~= nil)) then badOut(FNAME, out, 3) end
  local r1 = body1._parent and root(body1) or body1
  local r2 = body2._parent and root(body2) or body2
  if r1 == r2 then return false end -- every leaf pair would share a root
  if s1 and s2 then
    -- One leaf each, the common case: straight-line code (LuaJIT traces one-trip loops
    -- badly), tested into the caller's `out` when there is one.
    if s1[DIRTY] then s1:_refresh() end
    if s2[DIRTY] then s2:_refresh() end
    if s1[MAXX] < s2[MINX] or s2[MAXX] < s1[MINX] or s1[MAXY] < s2[MINY] or s2[MAXY] < s1[MINY] then
      return false -- the bounds do not even meet
    end
    -- (an empty row for a `_kind` a game changed: noKernel says so)
    local collide = collideOf[s1._kind][s2._kind]
    if not collide then args.noKernel(FNAME, s1, s2, body1, body2) end
    local m = collide(s1, s2, out or tmpA)
    if not out then -- (tested into tmpA: a copy goes out, and tmpA lets go of the shapes)
      local hit = m.depth > 0
      if hit then out = MTV._set(MTV(), m) end
      letGo(m)
      if not hit then return false end
    elseif not (m.depth > 0) then -- luacheck: ignore 581 (NaN reads as no collision)
      return false
    end
    out.collider, out.collided = r1, r2
    out._poseA, out._poseB = s1._pose, s2._pose
    return out
  end
  local l1, n1, l2, n2
  if s1 == body1 then l1, n1 = one1, 1; one1[1] = body1 else l1, n1 = leafList(body1) end
  if s2 == body2 then l2, n2 = one2, 1; one2[1] = body2 else l2, n2 = leafList(body2) end
  -- The solid pairs first (chain segments are surfaces, not solids: they keep their own
  -- per-segment answer, below). Test into `tmp`; a deeper result becomes `best` and the
  -- other buffer becomes `tmp`. With an `out` table it is one of the two buffers, so the
  -- usual single hit needs no copy.
  local best, tmp, found, chains = tmpA, out or tmpB, 0, false
  local bestDepth = 0
  for i = 1, n1 do
    local a = l1[i]
    if a[DIRTY] then a:_refresh() end
    local ax0, ay0, ax1, ay1 = a[MINX], a[MINY], a[MAXX], a[MAXY]
    local row = collideOf[a._kind]
    for j = 1, n2 do
      local b = l2[j]
      if b[DIRTY] then b:_refresh() end
      -- Bounds meet (closed intervals: an axis-aligned edge or a point has a flat box;
      -- the narrow phase decides touching), as two tests instead of four: fewer trace
      -- exits under LuaJIT.
      if min(ax1, b[MAXX]) >= max(ax0, b[MINX]) and min(ay1, b[MAXY]) >= max(ay0, b[MINY]) then
        if a._kind == 'chain' or b._kind == 'chain' then
          chains = true
        else
          local collide = row[b._kind]
          if not collide then args.noKernel(FNAME, a, b, body1, body2) end
          collide(a, b, tmp)
          local d = tmp.depth
          if d > 0 then -- (false for NaN and for separating results)
            found = found + 1
            if d > bestDepth then best, tmp, bestDepth = tmp, best, d end
          end
        end
      end
    end
  end
  -- Several members: the shortest push out of them all (outline.lua), unless the deepest
  -- pair's own is that already.
  if found > 0 and n1 + n2 > 2 then
    -- (the outline reads every member's kind: one a game changed is an error, not a solid)
    for i = 1, n1 do
      if not kinds[l1[i]._kind] then args.noKernel(FNAME, l1[i], l2[1], body1, body2) end
    end
    for j = 1, n2 do
      if not kinds[l2[j]._kind] then args.noKernel(FNAME, l1[1], l2[j], body1, body2) end
    end
    resolve(best, l1, n1, l2, n2)
    bestDepth = best.depth
  end
  if chains then -- the chain segments' pairs: the deepest, when deeper than the solids'
    for i = 1, n1 do
      local a = l1[i]
      local ax0, ay0, ax1, ay1 = a[MINX], a[MINY], a[MAXX], a[MAXY]
      local row = collideOf[a._kind]
      local chainA = a._kind == 'chain'
      for j = 1, n2 do
        local b = l2[j]
        if (chainA or b._kind == 'chain')
          and min(ax1, b[MAXX]) >= max(ax0, b[MINX]) and min(ay1, b[MAXY]) >= max(ay0, b[MINY]) then
          local collide = row[b._kind]
          if not collide then args.noKernel(FNAME, a, b, body1, body2) end
          collide(a, b, tmp)
          local d = tmp.depth
          if d > bestDepth then best, tmp, bestDepth, found = tmp, best, d, found + 1 end
        end
      end
    end
  end
  one1[1], one2[1] = nil, nil -- (bare shapes are not kept alive by strike)
  if found > 0 then
    if best ~= out then out = MTV._set(out or MTV(), best) end
    stamp(out, r1, r2)
  end
  -- (nor members by the scratch MTVs: a member removed from its body stays dead)
  if tmpA ~= out then letGo(tmpA) end
  if tmpB ~= out then letGo(tmpB) end
  return found > 0 and out
end

-- A member pair whose depth along its own normal is at most this fraction of the push's
-- length only slid along the push: touching, not colliding, and no contact.
local SLIDE = 1e-9

-- The sum over the leaves (refreshed here) of their extent and distance from the origin:
-- the size of round-off in the contacts' tests.
local function sizes(list, n)
  local sum = 0
  for i = 1, n do
    local s = list[i]
    if s[DIRTY] then s:_refresh() end
    sum = sum + (s[MAXX] - s[MINX]) + (s[MAXY] - s[MINY]) + abs(s[MINX]) + abs(s[MINY])
  end
  return sum
end

--- The contact points of a compound MTV (bodies with more than one leaf between them, and
--- an answer from solid members; see S.ite): every solid member pair that touches once the
--- second body has moved by the MTV, with a depth along its own normal more than SLIDE of
--- the MTV's (outline.feature), gives its points (at most 2, from contact.pushed: where the
--- pair touches after the move, along the face it touches along, with that face's normal
--- and the pair's own depth along it, at most the MTV's), in leaf order; each point names
--- its members (colliderShape, collidedShape) and its normal (nx, ny). Fills `out` from
--- index 1 and returns the count (0: none).
---@param m table the MTV (x, y, nx, ny, depth)
---@param l1 strike.Shape[]
---@param n1 integer
---@param l2 strike.Shape[]
---@param n2 integer
---@param out table
---@return integer count
function compound.contacts(m, l1, n1, l2, n2, out)
  local tx, ty, ux, uy, len = m.x, m.y, m.nx, m.ny, m.depth
  local scale = (abs(tx) + abs(ty) + sizes(l1, n1) + sizes(l2, n2)) / (n1 + n2)
  local tol = 1e3 * outline.TOL * scale -- (the push was computed with round-off of its own)
  -- (a pair the push slides along has a depth of 0 but for round-off, of the push's size; the
  -- touching tolerance, of the scene's, can be larger than a small push)
  local minDepth = SLIDE * len
  local count = 0
  for i = 1, n1 do
    local a = l1[i]
    if solid(a) then
      for j = 1, n2 do
        local b = l2[j]
        if solid(b) then
          -- (a `_kind` a game changed: said, not read as a polygon's)
          if not kinds[a._kind] or not kinds[b._kind] then args.noKernel('strike.ite', a, b) end
          local nx, ny, depth, face, ia, ib = feature(a, b, tx, ty, ux, uy, tol, minDepth)
          if nx then
            if depth > len then depth = len end -- (n . t, |n| = 1 to round-off)
            local k = pushed(a, b, tx, ty, nx, ny, depth, face, ia, ib, tol, out, count)
            for q = count + 1, count + k do
              local p = out[q]
              p.nx, p.ny, p.colliderShape, p.collidedShape = nx, ny, a, b
            end
            count = count + k
          end
        end
      end
    end
  end
  return count
end

return compound
