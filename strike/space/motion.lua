--- Motion in a space: Space:cast (the first body a move would hit) and Space:move (move and
--- resolve what it meets, bump-style), with responses (Space:addResponse). Loaded by
--- strike/init.lua after Space.lua, whose internals it shares (Space._internals: its query
--- levels, flush, the candidates of a box and the pair rules).
---
--- Sweeps, not teleports: every leg of a move is a time-of-impact query against the bodies
--- whose boxes meet the leg's swept box (motion/sweep.lua), so nothing tunnels at any speed.
---
--- move, step by step. From the body's centroid toward the goal:
---  1. the first hit of the leg among the bodies that the layers, masks, groups, the pair
---     filter and `filter(body, other)` allow (a response name; nil: ignore that body); a
---     body passed through ('cross') or met with a game's own response is not met again in
---     the move; sensors are skipped (their events come from collisions()). A body
---     overlapping at the start counts only when the move goes further into it;
---  2. the body stops just short of the touch: half its skin (SKIN times its size) along the
---     normal, taken back along the leg, so that the next leg starts apart from what it
---     touched (a leg that slides along a surface then never meets the seams of the tiles
---     that make it). A leg met only because the body is over the side of what it met by at
---     most the skin goes on shifted across instead (an exact fit: graze);
---  3. the response (Space:addResponse) gives where the next leg starts and its goal; a
---     slide that turns back into the surface slid along just before (a corner) stops. At
---     most MAX_LEGS legs turn the move; those that pass a body and go on unchanged
---     ('cross') are not counted, so a move crosses any number of bodies.
--- Casts and moves are refused outside the range of motion (limits.lua), before anything moves.
--- The candidates of a leg are kept for the next legs and moves while nothing else in the
--- space moves (Space.lua's _version), in a box padded by the body's radius and the move's
--- length when the same body moves again (see Space:move); the body's own place in the
--- broadphase waits for the next query that needs it.
--- The collision records (`other`, `type`, `t`, `nx`, `ny`, `touchX`, `touchY`, `x`, `y`,
--- `overlapping`) and the list are the space's, reused by the next move.
local ROOT = (...):match('^(.-)%.space%.[^%.]+$')
local sweep = require(ROOT .. '.motion.sweep')
local compound = require(ROOT .. '.collide.compound')
local check = require(ROOT .. '.check')
local MTV = require(ROOT .. '.collide.MTV')
local filter = require(ROOT .. '.space.filter')

local collide, translate, leavesOf, better = compound.collide, sweep.translate, sweep.leavesOf, sweep.better
local overlapHit = sweep.overlapHit
local kernels = require(ROOT .. '.motion.kernels')
local TIE = kernels.TIE
local limits = require(ROOT .. '.limits')
local ROUND, checkReach, CENTROID_REACH = limits.ROUND, limits.checkReach, limits.CENTROID_REACH
local layout = require(ROOT .. '.base.layout')
local DIRTY, MINX, MINY, MAXX, MAXY = layout.DIRTY, layout.MINX, layout.MINY, layout.MAXX, layout.MAXY
local queryFilter, checkQuery = filter.query, filter.checkQuery
local fail, describe, what, badSelf, finite = check.fail, check.describe, check.what, check.badSelf, check.finite
local unit, MAX_LENGTH = limits.unit, limits.MAX_LENGTH
local sqrt, abs, huge, type = math.sqrt, math.abs, math.huge, type

local Space = require(ROOT .. '.space.Space')
local private = Space._internals

local enter, leave, flush, candidates = private.enter, private.leave, private.flush, private.candidates
local allowed, isSpace, checkBody, idOf = private.allowed, private.isSpace, private.checkBody, private.idOf
local protect, present, ownId = private.protect, private.present, private.ownId

--- The skin: the most gap a move leaves between a body and what stops it, SKIN times the
--- body's size (its radius; for a point, the length of its move). A stop that cannot rest
--- exactly touching aims at half of it, so that the rounding of the coordinates keeps the gap
--- in (0, skin] (docs/moving.md, "Moving bodies in a space"; limits.lua, the range of motion).
Space.SKIN = 1e-6
--- The range of motion: casts and moves reach at most REACH sizes of the body from the
--- origin (limits.lua).
Space.REACH = limits.REACH

-- The skin of a body of size `size`.
local function skinAt(size) return Space.SKIN * size end

--- A move that starts overlapping a body meets it only when its part along the MTV, into the
--- body, is more than INTO of its length plus limits.ROUND of its largest coordinate: a slide
--- along a body leaves the rest of the move a few units in the last place into it, and a move
--- that met it again for that would slide leg after leg without going anywhere.
Space.INTO = 1e-12
local INTO = Space.INTO

local mtv = MTV()
local hitScratch = {}

-- The first body the body `b` (id `self_id` when in this space, else false) hits moving by
-- (dx, dy), among the candidates of `level`: the hit in `out` (plus out.body) or false.
-- `pick(other, id)` says whether other may be hit: a truthy value (kept in out.pick), or
-- false. `away`: a body overlapping at the start counts only when the move goes further in.
-- The candidates are those of the box the move sweeps (the broadphase brought up to date
-- first). With `cache` (a move's), they are those of a larger box kept from an earlier leg or
-- move while nothing but the body moving has moved (the body itself waits in the queue).
-- `game`: pick may run the game's code (a filter function, the pair filter), which may
-- remove bodies: a body removed is not hit, nor is one removed after it was (the hits are
-- kept in level.hits to choose again from); moving the body `b` itself is an error.
-- `skin`: a leg of a move, whose first hit may be an exact fit (see graze).
-- The tolerance of ties between two bodies' hits in first, in t: the sweeps' tolerance for
-- the neighbourhood of the mover (its box at the start, a0-a1; the box it sweeps, x0-x1), as
-- kernels.lua's Tolerances: far less than the skin a stop leaves, in the range of motion.
local function tieOf(x0, y0, x1, y1, ax0, ay0, ax1, ay1, dl)
  if dl == 0 then return 0 end
  local m = x1 > -x0 and x1 or -x0 -- (the largest coordinate of the box swept: kernels.reach)
  if y1 > m then m = y1 end
  if -y0 > m then m = -y0 end
  return (TIE * ((ax1 - ax0) + (ay1 - ay0)) + ROUND * m) / dl
end

-- A filter moved the body being moved, or added or removed a member of it: an error.
local function moverChanged(away)
  fail(('%s: a filter moved the body being moved, or added or removed a member of it (move or change'
    .. ' other bodies only, or change the goal)'):format(away and 'strike.Space:move' or 'strike.Space:cast'))
end

local function first(self, level, b, self_id, dx, dy, pick, ctx, away, out, cache, pad, game, skin)
  local x0, y0, x1, y1 = b:getBounds()
  local ax0, ay0, ax1, ay1 = x0, y0, x1, y1
  if dx < 0 then x0 = x0 + dx else x1 = x1 + dx end
  if dy < 0 then y0 = y0 + dy else y1 = y1 + dy end
  local ids, n
  if cache then
    n = cache.n
    if not (cache.version == self._version and cache.x0 <= x0 and cache.y0 <= y0 and cache.x1 >= x1
      and cache.y1 >= y1) then
      flush(self)
      local qx0, qy0, qx1, qy1 = x0 - pad, y0 - pad, x1 + pad, y1 + pad
      n = candidates(self, cache, qx0, qy0, qx1, qy1)
      cache.n, cache.version, cache.x0, cache.y0, cache.x1, cache.y1 = n, self._version, qx0, qy0, qx1, qy1
    end
    ids = cache.ids
  else
    flush(self)
    n = candidates(self, level, x0, y0, x1, y1)
    ids = level.ids
  end
  local bodies, sensor = self._body, self._sensor
  -- (one-leaf lists of the level's own: a filter may sweep another body meanwhile)
  local one1, one2 = level.one1, level.one2
  if not one1 then
    one1, one2 = {}, {}
    level.one1, level.one2 = one1, one2
  end
  local la, na = leavesOf(b, one1)
  local found, bt, bcorner, badn = false, huge, false, huge
  local ox0, oy0, ox1, oy1 = 0, 0, 0, 0 -- (the bounds of the body hit, for an exact fit)
  local dl = sqrt(dx * dx + dy * dy)
  local removals, pose, hits, nh = 0, false, false, 0
  if game then removals, pose, hits = self._removals, na > 0 and la[1]._pose, level.hits end
  -- (ties between bodies: within the sweeps' tolerance for the mover's neighbourhood, as
  -- kernels.lua's Tolerances, in t: far less than the skin a stop leaves, in the range of motion;
  -- computed when a second hit is found)
  local tieT = -1
  for c = 1, n do
    local id = ids[c]
    local other = bodies[id]
    if other and id ~= self_id and not sensor[id] then
      -- (the exact bounds first: a candidate of a larger box is often outside the leg's)
      local bx0, by0, bx1, by1
      if other._pose then
        if other[DIRTY] then other:_refresh() end
        bx0, by0, bx1, by1 = other[MINX], other[MINY], other[MAXX], other[MAXY]
      elseif other._clean then -- (a collider's bounds slots, valid while it is clean)
        bx0, by0, bx1, by1 = other[MINX], other[MINY], other[MAXX], other[MAXY]
      else
        bx0, by0, bx1, by1 = other:getBounds()
      end
      local p = bx0 <= x1 and bx1 >= x0 and by0 <= y1 and by1 >= y0
      if p then
        p = pick(ctx, other, id)
        -- (the game's filter ran: it may not have changed the body being moved, whose leaves
        -- the sweeps below read; a member removed or added leaves a collider unclean, and so
        -- does a move, as it changes the first leaf's pose stamp)
        if game and (b._clean == false or (na > 0 and la[1]._pose ~= pose)) then moverChanged(away) end
      end
      if p then
        local t, x, y, nx, ny, corner, overlapping
        if away then
          -- A move: the sweep first, and S.triking only for a body it found overlapping at the
          -- start. (A body partly through a chain segment passes on: a one-way platform it
          -- jumped into from below lets it through, or fall back, instead of holding it.)
          local lb, nb = leavesOf(other, one2)
          if na > 0 and nb > 0 then
            if translate(la, na, lb, nb, dx, dy) then
              t, x, y, nx, ny, corner, overlapping = sweep.t, sweep.x, sweep.y, sweep.nx, sweep.ny, sweep.corner,
                false
            end
            if sweep.overlap then
              local m = collide(b, other, mtv)
              if m and m.collidedShape._kind ~= 'chain' and m.colliderShape._kind ~= 'chain' then
                t = nil
                -- (only when the move goes further in: by more than INTO of its length and the
                -- rounding of its coordinates, what a slide along that body leaves of the move
                -- into it)
                local r = x1 > -x0 and x1 or -x0
                if y1 > r then r = y1 end
                if -y0 > r then r = -y0 end
                if dx * m.nx + dy * m.ny > INTO * dl + ROUND * r then
                  overlapHit(m, hitScratch)
                  t, x, y, nx, ny, corner, overlapping = 0, hitScratch.x, hitScratch.y, hitScratch.nx, hitScratch.ny,
                    false, true
                end
              end
            end
          end
        else -- a cast: S.weep's answer
          local m = collide(b, other, mtv)
          if m then
            overlapHit(m, hitScratch)
            t, x, y, nx, ny, corner, overlapping = 0, hitScratch.x, hitScratch.y, hitScratch.nx, hitScratch.ny,
              false, true
          elseif na > 0 then
            local lb, nb = leavesOf(other, one2)
            if nb > 0 and translate(la, na, lb, nb, dx, dy) then
              t, x, y, nx, ny, corner, overlapping = sweep.t, sweep.x, sweep.y, sweep.nx, sweep.ny, sweep.corner,
                false
            end
          end
        end
        if t then
          local adn = abs(dx * nx + dy * ny)
          if found and tieT < 0 then tieT = tieOf(x0, y0, x1, y1, ax0, ay0, ax1, ay1, dl) end
          if not found or better(t, corner, adn, bt, bcorner, badn, tieT) then
            found, bt, bcorner, badn = true, t, corner, adn
            out.t, out.x, out.y, out.nx, out.ny, out.overlapping = t, x, y, nx, ny, overlapping
            out.body, out.pick = other, p
            ox0, oy0, ox1, oy1 = bx0, by0, bx1, by1
          end
          if game then
            if not hits then
              hits = {}
              level.hits = hits
            end
            hits[nh + 1], hits[nh + 2], hits[nh + 3], hits[nh + 4], hits[nh + 5] = other, t, x, y, nx
            hits[nh + 6], hits[nh + 7], hits[nh + 8], hits[nh + 9], hits[nh + 10] = ny, corner, overlapping, adn, p
            nh = nh + 10
          end
        end
      end
    end
  end
  if game then
    local rechosen = found and self._removals ~= removals and not present(self, out.body)
    if rechosen then
      -- (a filter removed the body hit after it was found: the first of those left; no exact
      -- fit is looked for then)
      found = false
      if tieT < 0 then tieT = tieOf(x0, y0, x1, y1, ax0, ay0, ax1, ay1, dl) end
      for h = 1, nh, 10 do
        local other, t, corner, adn = hits[h], hits[h + 1], hits[h + 6], hits[h + 8]
        if present(self, other) and (not found or better(t, corner, adn, bt, bcorner, badn, tieT)) then
          found, bt, bcorner, badn = true, t, corner, adn
          out.t, out.x, out.y, out.nx, out.ny, out.overlapping = t, hits[h + 2], hits[h + 3], hits[h + 4],
            hits[h + 5], hits[h + 7]
          out.body, out.pick = other, hits[h + 9]
        end
      end
    end
    for h = 1, nh do hits[h] = false end -- (nothing kept alive)
    if rechosen then
      if not found then out.body, out.pick = nil, nil end
      out.fit = false
      return found
    end
  end
  if skin and found then
    -- (a leg of a move: may it be an exact fit? At the stop, the overlaps across of the body
    -- hit over the moving body's sides (l, r; u, d along y): an exact fit needs one in [0,
    -- skin], where (2 ov - skin)^2 <= skin^2; the common case takes no branch, and LuaJIT's
    -- traces stay whole. See graze)
    local dn = -(dx * out.nx + dy * out.ny)
    local ts = bt
    if dn > 0 then ts = ts - skin * 0.5 / dn end
    if ts < 0 then ts = 0 end
    local mx, my = ts * dx, ts * dy
    ax0, ay0, ax1, ay1 = ax0 + mx, ay0 + my, ax1 + mx, ay1 + my
    local l, r, u, d = ox1 - ax0, ax1 - ox0, oy1 - ay0, ay1 - oy0
    local ql, qr, qu, qd, s2 = l + l - skin, r + r - skin, u + u - skin, d + d - skin, skin * skin
    if ql * ql <= s2 or qr * qr <= s2 or qu * qu <= s2 or qd * qd <= s2 then
      local sx, sy = 0, 0
      if l > 0 and l <= skin and ox0 < ax0 then sx = l
      elseif r > 0 and r <= skin and ox1 > ax1 then sx = -r
      elseif u > 0 and u <= skin and oy0 < ay0 then sy = u
      elseif d > 0 and d <= skin and oy1 > ay1 then sy = -d end
      if sx ~= 0 or sy ~= 0 then
        out.fit, out.mx, out.my, out.sx, out.sy = true, mx, my, sx, sy
        return true
      end
    end
    out.fit = false
  end
  return found
end

------------------------------------------------------------------ cast

-- The pair rules between the body a query moves (its id sid, in this space) and body id.
local function pairAllowed(self, sid, id)
  if self._rank[sid] < self._rank[id] then return allowed(self, sid, id) end
  return allowed(self, id, sid)
end

-- cast's rule for a candidate: the query filter, and the pair rules for a body in the space.
local function castPick(level, other, id)
  local self = level.space
  if not queryFilter(level.filter, other, self._layer[id]) or self._body[id] ~= other then return false end
  local sid = level.sid
  -- (the filter may have removed the body cast: it is then cast as a body of no space)
  return not sid or self._body[sid] ~= level.body or pairAllowed(self, sid, id)
end

local function castOf(self, body, dx, dy, filterArg, out, game)
  flush(self)
  local sid = ownId(self, 'strike.Space:cast', body) -- (false when it is not in this space)
  if sid and self._sensor[sid] then return false end
  local level = enter(self)
  level.filter, level.sid, level.body = filterArg, sid, body
  local found = first(self, level, body, sid, dx, dy, castPick, level, false, out, nil, 0, game)
  leave(self, level)
  level.filter, level.sid, level.body = false, false, false
  local one1, one2 = level.one1, level.one2 -- (the one-leaf lists keep no body alive)
  if one1 then one1[1], one2[1] = nil, nil end
  if not found then
    out.body, out.pick = nil, nil
    return false
  end
  out.pick = nil
  return out
end

--- The first body that `body` (in this space or not) would hit moving by (dx, dy): the hit
--- of S.weep (`t`, `x`, `y`, `nx`, `ny`, `overlapping`) plus `body`, the body hit, filled
--- into `out` when given; or false. Only bodies `filter` allows count (a function
--- (other) -> boolean or a layer filter); for a body in the space, layers, masks, groups
--- and the pair filter apply too. Sensors are never hit, and a sensor hits nothing. Ties go
--- to a face over a corner, then to the body the move grazes most, then to the body added
--- first.
---@param body strike.Collider|strike.Shape
---@param dx number
---@param dy number
---@param filterArg function|table|nil
---@param out table|nil
---@return table|false
function Space:cast(body, dx, dy, filterArg, out)
  local F = 'strike.Space:cast'
  if not isSpace(self) then badSelf(self, F) end
  checkBody(F, body, 1)
  if not (finite(dx) and finite(dy)) then
    check.number(dx, F, 'argument 2 (dx)')
    check.number(dy, F, 'argument 3 (dy)')
  end
  checkQuery(filterArg, F, 4)
  if out ~= nil and (type(out) ~= 'table' or getmetatable(out) ~= nil) then
    fail(('%s: argument 5 (out) must be a plain table for the hit (a previous hit, or {}), got %s'):format(F,
      what(out)))
  end
  do -- (the range of motion: limits.lua)
    local x, y = body:getCentroid()
    checkReach(F, body:getRadius(), x, y, x + dx, y + dy)
  end
  out = out or {}
  local game = type(filterArg) == 'function' or self._pairFilter and ownId(self, F, body) and true or false
  if game and not self._guard then return protect(self, castOf, body, dx, dy, filterArg, out, game) end
  return castOf(self, body, dx, dy, filterArg, out, game)
end

------------------------------------------------------------------ move

local function slide(_, col, _, _, goalX, goalY)
  local tx, ty = col.touchX, col.touchY
  local rx, ry = goalX - tx, goalY - ty
  local nx, ny = col.nx, col.ny
  local rn = rx * nx + ry * ny
  if rn < 0 then rx, ry = rx - rn * nx, ry - rn * ny end
  return tx, ty, tx + rx, ty + ry
end

local function touch(_, col)
  return col.touchX, col.touchY, col.touchX, col.touchY
end

local function cross(_, _, x, y, goalX, goalY)
  return x, y, goalX, goalY
end

local function bounce(_, col, _, _, goalX, goalY)
  local tx, ty = col.touchX, col.touchY
  local rx, ry = goalX - tx, goalY - ty
  local nx, ny = col.nx, col.ny
  local rn = rx * nx + ry * ny
  if rn < 0 then rx, ry = rx - 2 * rn * nx, ry - 2 * rn * ny end
  return tx, ty, tx + rx, ty + ry
end

-- The responses every space has; a space's own ones (addResponse) are in self._responses.
local RESPONSES = { slide = slide, touch = touch, cross = cross, bounce = bounce }

--- Add a response for move's filters to name: `fn(space, col, x, y, goalX, goalY)` is called
--- when the body meets col.other, with (x, y) where the leg started and its goal, and
--- returns where the next leg starts and its goal (`fromX, fromY, goalX, goalY`; the body
--- stays where it is when they are equal). The built-in ones ('slide', 'touch', 'cross',
--- 'bounce') cannot be replaced.
---@param name string
---@param fn function
function Space:addResponse(name, fn)
  local F = 'strike.Space:addResponse'
  if not isSpace(self) then badSelf(self, F) end
  if type(name) ~= 'string' then
    fail(('%s: argument 1 (name) must be a string, got %s'):format(F, describe(name)))
  end
  if RESPONSES[name] then fail(('%s: %q is a built-in response and cannot be replaced'):format(F, name)) end
  if type(fn) ~= 'function' then
    fail(('%s: argument 2 must be a function (space, col, x, y, goalX, goalY), got %s'):format(F, what(fn)))
  end
  local own = rawget(self, '_responses')
  if not own then
    own = {}
    self._responses = own
  end
  own[name] = fn
end

-- move's response to body `other` (id): false when the pair rules forbid it or the filter
-- says nil, else the filter's response name ('slide' without a filter).
local function response(level, other, id)
  local self = level.space
  if not pairAllowed(self, level.sid, id) then return false end
  local f = level.filter
  if not f then return 'slide' end
  -- (the pair filter may have removed it, or the body moved: the move filter is asked about
  -- bodies of the space only)
  if self._body[id] ~= other or self._body[level.sid] ~= level.body then return false end
  local name = f(level.body, other)
  if name == nil or name == false then return false end
  return name
end

-- move's rule for a candidate: not met already (see the header), and its response.
local function movePick(level, other, id)
  if level.visited[other] then return false end
  return response(level, other, id)
end

-- The record for the k-th collision of a move: the list's own, or one kept from a longer
-- list before (cols.spare), or a new one.
local function colAt(cols, k)
  local col = cols[k]
  if col then return col end
  local spare = cols.spare
  local n = #spare
  if n > 0 then
    col = spare[n]
    spare[n] = nil
  else
    col = { other = false, type = 'slide', t = 0, nx = 0, ny = 0, touchX = 0, touchY = 0, x = 0, y = 0,
      overlapping = false }
  end
  cols[k] = col
  return col
end

-- The options of a move, validated (before anything moves): the up direction, the cosine of
-- the steepest walkable slope (false: none), the snap and step heights (0: none). Each move
-- keeps them in its level (enter): a move run from a filter of another has its own, and
-- one that fails leaves the other's as they were.
local OPTS = { up = true, slope = true, snap = true, step = true }

-- The error for a snap or step height that is no length from 0 to MAX_LENGTH.
local function badLength(F, key, v)
  fail(('%s: %s must be a length from 0 to %g, got %s'):format(F, key, MAX_LENGTH, describe(v)))
end

local function readOptions(F, opts)
  if opts == nil then return 0, -1, false, 0, 0 end
  if type(opts) ~= 'table' then
    fail(('%s: argument 5 (options) must be a table such as {slope = math.rad(50), snap = 4, step = 8}, got %s')
      :format(F, what(opts)))
  end
  if getmetatable(opts) ~= nil then
    local w = what(opts)
    fail(('%s: argument 5 (options) must be a plain table such as {slope = math.rad(50), snap = 4, step = 8},'
      .. ' got %s'):format(F, w == 'table' and 'a table with a metatable' or w))
  end
  local unknown = check.unknownKey(opts, OPTS)
  if unknown ~= nil then
    fail(('%s: unknown option %s (options are up, slope, snap and step)'):format(F, describe(unknown)))
  end
  local upX, upY, walkCos = 0, -1, false
  local up = opts.up
  if up ~= nil then
    if type(up) ~= 'table' then fail(('%s: up must be a direction {x, y}, got %s'):format(F, what(up))) end
    local ux, uy = up[1], up[2]
    if not (finite(ux) and finite(uy)) then
      fail(('%s: up must be a direction {x, y} of two finite numbers, got {%s, %s}'):format(F, describe(ux),
        describe(uy)))
    end
    -- (scaled by the larger component first: {1e-200, 1e-200} squared would underflow to 0)
    local x, y = unit(ux, uy)
    if not x then fail(('%s: up must be a direction {x, y}, not {0, 0}'):format(F)) end
    upX, upY = x, y
  end
  local slope = opts.slope
  if slope ~= nil then
    if not finite(slope) or slope < 0 or slope >= math.pi / 2 then
      fail(('%s: slope must be an angle in radians from 0 to less than pi / 2, got %s'):format(F, describe(slope)))
    end
    walkCos = math.cos(slope)
  end
  local snap, step = opts.snap, opts.step
  -- (lengths, as a shape's are: at most MAX_LENGTH; 0, or a tiny one, is none)
  if snap ~= nil and not (finite(snap) and snap >= 0 and snap <= MAX_LENGTH) then badLength(F, 'snap', snap) end
  if step ~= nil and not (finite(step) and step >= 0 and step <= MAX_LENGTH) then badLength(F, 'step', step) end
  return upX, upY, walkCos, snap or 0, step or 0
end

-- Can the body stand on a surface of normal (nx, ny)? (Any surface facing up when no slope
-- is given.)
local function walkable(level, nx, ny)
  local c = nx * level.upX + ny * level.upY
  local walkCos = level.walkCos
  if walkCos then return c >= walkCos end
  return c > 0.7
end

-- The slide on walkable ground: the remaining motion keeps its part across `up` and
-- follows the surface; its downward part is dropped (no sliding down a slope). A motion
-- going up (a jump) slides as usual.
local function groundSlide(level, col, goalX, goalY)
  local upX, upY = level.upX, level.upY
  local tx, ty = col.touchX, col.touchY
  local rx, ry = goalX - tx, goalY - ty
  local ru = rx * upX + ry * upY
  local nx, ny = col.nx, col.ny
  if ru > 0 then return slide(nil, col, 0, 0, goalX, goalY) end
  local hx, hy = rx - ru * upX, ry - ru * upY
  local l = -(hx * nx + hy * ny) / (upX * nx + upY * ny)
  return tx, ty, tx + hx + l * upX, ty + hy + l * upY
end

-- move's rule for the extra casts of a step and a snap: every body the body would not
-- pass through (a response other than 'cross'), met before in this move or not (a body met
-- with a response of the game's, which may have stopped the move there, is solid to them).
local function solidPick(level, other, id)
  local name = response(level, other, id)
  if name == 'cross' then return false end
  return name
end

-- Cast the body by (dx, dy) against solid bodies and move it as far as it goes, half its skin
-- short (`skin`: the body's skin):
-- the fraction moved, and whether it hit something, with the normal there. (The hit goes in
-- the level's own table: a filter may move another body meanwhile.)
local function advance(self, level, body, sid, dx, dy, skin)
  local probe = level.stepHit
  if not probe then
    probe = {}
    level.stepHit = probe
  end
  local h = first(self, level, body, sid, dx, dy, solidPick, level, true, probe, nil, 0, level.game)
  local ts, nx, ny = 1, 0, 0
  if h then
    nx, ny = probe.nx, probe.ny
    local dn = -(dx * nx + dy * ny)
    ts = probe.t
    if probe.overlapping then ts = 0 elseif dn > 0 then ts = ts - skin * 0.5 / dn end
    if ts < 0 then ts = 0 end
    probe.body, probe.pick = nil, nil
  end
  if ts > 0 then body:translate(ts * dx, ts * dy) end
  return ts, h, nx, ny
end

-- Try to step up a ledge at most stepH high while moving across `up` by (hx, hy): up, across,
-- then down onto walkable ground. Returns true with the body there, or false with the body
-- back where it was.
local function stepUp(self, level, body, sid, hx, hy, skin)
  local upX, upY, stepH = level.upX, level.upY, level.stepH
  local x0, y0 = body:getCentroid()
  local tu = advance(self, level, body, sid, upX * stepH, upY * stepH, skin)
  if tu > 0 then
    local th = advance(self, level, body, sid, hx, hy, skin)
    if th > 0 then
      local up = tu * stepH
      local td, h, nx, ny = advance(self, level, body, sid, -upX * up, -upY * up, skin)
      if h and td < 1 and walkable(level, nx, ny) then return true end
    end
  end
  local x, y = body:getCentroid()
  body:translate(x0 - x, y0 - y)
  return false
end

-- The most legs of a move that slide, touch or bounce, or that a response turns (a new start
-- or goal). At one more (a body bouncing between two walls with a long move, or a game's
-- response that keeps turning it), the body stops where that leg's response put it (for
-- the built-in ones the touch, a skin short of what it met: the last safe point), and the
-- collision is reported. Legs that go on unchanged past a body ('cross', or a game's
-- response that returns the leg as it was) do not count: each passes a body that the move
-- then never meets again, so they end, and a move crosses any number of bodies.
local MAX_LEGS = 64

-- An exact fit (docs/moving.md, exact fits). A leg that meets a body only because at
-- its stop there the body overlaps the other's side by at most its skin (the gap a stop keeps
-- from a wall slid along, say) goes on from that stop shifted across by the overlap, when
-- S.triking finds the body there apart from every solid body around it (touching is not
-- colliding): it then touches both sides, and a body slides into a gap exactly its size.
-- `hit` is first's, which found the fit may be one (hit.fit): the stop (mx, my) along the leg
-- and the shift (sx, sy). Returns the body moved to the stop and shifted, and true; or false
-- with the body where it was.
local function graze(self, level, body, sid, hit)
  local sx, sy = hit.sx, hit.sy
  local mx, my = hit.mx + sx, hit.my + sy
  body:translate(mx, my)
  local x0, y0, x1, y1 = body:getBounds()
  -- (there, apart from everything it would not pass through: the stop is clear of everything
  -- as any stop is, and the shift is no longer than the skin, so nothing lies wholly beyond it.
  -- Should the shift round a unit in the last place past the other's side, the leg meets the
  -- other again as it goes on, and stops: a face it runs along is crossed as S.triking decides)
  flush(self)
  local n = candidates(self, level, x0, y0, x1, y1)
  local ids, bodies, sensor = level.ids, self._body, self._sensor
  for c = 1, n do
    local id = ids[c]
    local o = bodies[id]
    -- (solidPick may run the game's filter, which may remove the body it is asked about)
    if o and id ~= sid and not sensor[id] and solidPick(level, o, id) and bodies[id] == o and collide(body, o, mtv)
    then
      body:translate(-mx, -my)
      return false
    end
  end
  return true
end

-- A leg of a move from (x, y) toward (goalX, goalY) whose first hit (`hit`) may be an exact
-- fit (hit.fit): the fit when graze finds one, then the leg's first hit from there. Returns
-- whether the leg hits, where it starts and its goal (shifted with the body).
local function fitLeg(self, level, body, sid, hit, x, y, goalX, goalY, cache, pad, skin)
  if not graze(self, level, body, sid, hit) then return true, x, y, goalX, goalY end
  hit.body, hit.pick = nil, nil
  local sx, sy = hit.sx, hit.sy
  x, y, goalX, goalY = x + hit.mx + sx, y + hit.my + sy, goalX + sx, goalY + sy
  return first(self, level, body, sid, goalX - x, goalY - y, movePick, level, true, hit, cache, pad, level.game, skin),
    x, y, goalX, goalY
end


-- The collision list of the level a move runs at (one for moves at the top, another for a
-- move run from a filter of a query or of another move, and so on), with the marks of the
-- bodies met and the hit scratch.
local function listOf(self, level)
  local lists = rawget(self, '_cols')
  if not lists then
    lists = {}
    self._cols = lists
  end
  local depth = level.index
  local cols = lists[depth]
  if not cols then
    cols = { visited = {}, hit = {}, spare = {}, cache = { ids = {}, n = 0, version = -1, x0 = 0, y0 = 0, x1 = 0,
      y1 = 0, sid = 0 } }
    lists[depth] = cols
  end
  return cols
end

--- Move a body of this space so that its centroid goes toward (goalX, goalY), resolving what
--- it meets on the way (see the header): returns the centroid it reached, the list of
--- collisions in the order they happened and their count. `filter(body, other)` returns a
--- response name for each other body ('slide', the default without a filter; 'touch',
--- 'cross', 'bounce', or one added with addResponse), or nil to pass through it unreported.
--- Each collision is `{other =, type =, t =, nx =, ny =, touchX =, touchY =, x =, y =,
--- overlapping =}`: t the fraction of its leg at the touch, (nx, ny) the unit normal from
--- other toward body, (touchX, touchY) the centroid where the body touched, (x, y) the
--- contact point. The list and its records are reused by the next move. The filter and the
--- responses may add, remove, move and query other bodies (docs/space.md); a body
--- they remove is not met after; removing the body being moved ends the move there, and
--- moving it is an error.
--- Options for characters (docs/moving.md, "Characters"): `up` (a direction {x, y} of any finite
--- length but 0; default {0, -1}, up on a LÖVE screen), `slope` (the steepest walkable
--- slope, radians: on walkable ground a slide keeps the motion across `up` and never slides
--- down), `snap` (a move that does not go up ends on walkable ground within this distance
--- below, when there is some: no hops down a slope or a stair), `step` (a slide into a wall
--- first tries to climb a ledge up to this high); snap and step are lengths from 0 to 1e100.
---@param body strike.Collider|strike.Shape
---@param goalX number
---@param goalY number
---@param filterFn function|nil
---@param opts table|nil
---@return number actualX
---@return number actualY
---@return table collisions
---@return integer count
function Space:move(body, goalX, goalY, filterFn, opts)
  local F = 'strike.Space:move'
  if not isSpace(self) then badSelf(self, F) end
  local sid = idOf(self, F, body)
  if not (finite(goalX) and finite(goalY)) then
    check.number(goalX, F, 'argument 2 (goalX)')
    check.number(goalY, F, 'argument 3 (goalY)')
  end
  if filterFn ~= nil and type(filterFn) ~= 'function' then
    fail(('%s: argument 4 (filter) must be a function (body, other) -> response name or nil, got %s'):format(F,
      what(filterFn)))
  end
  -- (the range of motion, limits.lua, tested inline; the size the skin is relative to)
  local x, y = body:getCentroid()
  local size = body:getRadius()
  local lim = CENTROID_REACH * size
  local nlim = -lim
  if not (x <= lim and x >= nlim and y <= lim and y >= nlim and goalX <= lim and goalX >= nlim and goalY <= lim
    and goalY >= nlim) then
    size = checkReach(F, size, x, y, goalX, goalY)
  end
  local upX, upY, walkCos, snapH, stepH = 0, -1, false, 0, 0
  if opts ~= nil then upX, upY, walkCos, snapH, stepH = readOptions(F, opts) end
  -- (the game's code runs in the move when it has a filter or the space a pair filter)
  local game = filterFn ~= nil or self._pairFilter and true or false
  local character = opts ~= nil -- (the walkable-ground slide: docs/moving.md, "Characters")
  if game and not self._guard then
    -- (protected: through this same function, which then finds the guard up and goes on; the
    -- checks above pass again, the game's code having run in neither)
    return protect(self, Space.move, body, goalX, goalY, filterFn, opts)
  end
  local level = enter(self)
  level.upX, level.upY, level.walkCos, level.snapH, level.stepH = upX, upY, walkCos, snapH, stepH
  local lists = rawget(self, '_cols')
  local cols = lists and lists[level.index] or listOf(self, level)
  local visited, hit = cols.visited, cols.hit
  -- (a move that a filter or response interrupted with an error left its marks: clear them)
  for i = 1, #cols do
    local c = cols[i]
    if c.other then visited[c.other] = nil end
  end
  local k = 0
  if self._sensor[sid] then -- (a sensor meets nothing: straight to the goal)
    body:translate(goalX - x, goalY - y)
    x, y = goalX, goalY
    leave(self, level)
  else
    local own = rawget(self, '_responses')
    level.filter, level.sid, level.body, level.visited, level.game = filterFn or false, sid, body, visited, game
    local skin = skinAt(size)
    local rising = (goalX - x) * upX + (goalY - y) * upY > 0
    -- The candidates are kept from leg to leg and from move to move while nothing but this
    -- body moves (Space.lua, _version), for a move at the top only (no other call under way:
    -- level 1, and no other move: _mover is 0), in a box padded by the body's radius and the
    -- move's length when this body made the last such move too (a player among still walls),
    -- else in the leg's own box: where every body moves in turn, the next mover's legs were
    -- never inside the last one's padded box, and the padding only made the tree query
    -- longer (bench/movers.lua, 2,000 movers, Lua 5.4: 2,613 -> 2,433 VM instructions a move;
    -- one body among 1,000 walls, bench/move.lua's workload: 2,585 either way).
    local cache, pad = nil, 0
    if level.index == 1 and self._mover == 0 then
      cache = cols.cache
      if cache.sid == sid then pad = size + sqrt((goalX - x) ^ 2 + (goalY - y) ^ 2) end
      cache.sid = sid
      self._mover = sid
    end
    local pnx, pny = 0, 0 -- (the normal of the last surface slid along)
    -- The legs that turn the move (see MAX_LEGS); a leg that passes a body through and goes
    -- on unchanged ('cross') costs none: each passes a new body, so they end.
    local legs = 0
    while true do
      local dx, dy = goalX - x, goalY - y
      if dx == 0 and dy == 0 then break end
      local met = first(self, level, body, sid, dx, dy, movePick, level, true, hit, cache, pad, game, skin)
      if game and not present(self, body) then break end -- (a filter removed the body: the move ends)
      if met and hit.fit and not hit.overlapping then -- (an exact fit, maybe: see graze)
        met, x, y, goalX, goalY = fitLeg(self, level, body, sid, hit, x, y, goalX, goalY, cache, pad, skin)
        if game and not present(self, body) then break end
        dx, dy = goalX - x, goalY - y
      end
      if not met then
        body:translate(dx, dy)
        x, y = goalX, goalY
        break
      end
      local t, nx, ny = hit.t, hit.nx, hit.ny
      -- stop short by half the skin along the normal, taken back along the leg (never before its
      -- start: nothing is met before t, so the body is clear of everything there)
      local dn = -(dx * nx + dy * ny)
      local ts = t
      if dn > 0 and not hit.overlapping then
        ts = t - skin * 0.5 / dn
        if ts < 0 then ts = 0 end
      end
      local tx, ty = x + ts * dx, y + ts * dy
      k = k + 1
      local col = colAt(cols, k)
      local name = hit.pick
      col.other, col.type, col.t, col.nx, col.ny = hit.body, name, t, nx, ny
      col.touchX, col.touchY, col.x, col.y, col.overlapping = tx, ty, hit.x, hit.y, hit.overlapping
      -- (a body passed through, or met with a response of the game's, is not met again in
      -- this move; one slid along, touched or bounced off can be: the rest of the move may
      -- turn back into it, in a corner)
      if name ~= 'slide' and name ~= 'touch' and name ~= 'bounce' then visited[hit.body] = true end
      hit.body, hit.pick = nil, nil
      local fn = RESPONSES[name] or own and own[name]
      if not fn then
        fail(('%s: the filter returned %s, which is not a response (slide, touch, cross, bounce, or one'
          .. ' added with addResponse)'):format(F, describe(name)))
      end
      local fx, fy, gx, gy
      if name == 'slide' and character and walkable(level, nx, ny) then
        fx, fy, gx, gy = groundSlide(level, col, goalX, goalY)
      elseif name == 'slide' and stepH > 0 and not walkable(level, nx, ny) then
        local rx, ry = goalX - tx, goalY - ty
        local ru = rx * upX + ry * upY
        local hx, hy = rx - ru * upX, ry - ru * upY
        if hx * nx + hy * ny < 0 then
          body:translate(tx - x, ty - y)
          x, y = tx, ty
          if stepUp(self, level, body, sid, hx, hy, skin) then
            local ux, uy = body:getCentroid()
            fx, fy, gx, gy = ux, uy, ux, uy -- (the step used the leg's motion across up)
            x, y = ux, uy
          end
        end
      end
      if not fx then fx, fy, gx, gy = fn(self, col, x, y, goalX, goalY) end
      if not (finite(fx) and finite(fy) and finite(gx) and finite(gy)) then
        fail(('%s: response %q must return four finite numbers (fromX, fromY, goalX, goalY), got %s, %s, %s, %s')
          :format(F, name, describe(fx), describe(fy), describe(gx), describe(gy)))
      end
      if name == 'slide' then
        -- In a corner: a slide along this surface that goes back into the last one slid along
        -- (a different one) would only bounce between the two; it stops there.
        local c = pnx * ny - pny * nx
        if (c > 1e-9 or c < -1e-9) and (gx - fx) * pnx + (gy - fy) * pny < 0 then gx, gy = fx, fy end
        pnx, pny = nx, ny
      end
      if game and not present(self, body) then break end -- (a filter or response removed it)
      if fx ~= x or fy ~= y or gx ~= goalX or gy ~= goalY or not visited[col.other] then
        legs = legs + 1
        if legs > MAX_LEGS then gx, gy = fx, fy end -- (the cap: it stops where this leg took it)
      end
      if fx ~= x or fy ~= y then body:translate(fx - x, fy - y) end
      x, y, goalX, goalY = fx, fy, gx, gy
    end
    if snapH > 0 and not rising and present(self, body) then -- snap down onto walkable ground
      if first(self, level, body, sid, -upX * snapH, -upY * snapH, solidPick, level, true, hit, nil, 0, game)
        and not hit.overlapping and walkable(level, hit.nx, hit.ny) then
        local ts = hit.t - skin * 0.5 / (snapH * (upX * hit.nx + upY * hit.ny))
        if ts > 0 then
          body:translate(-upX * snapH * ts, -upY * snapH * ts)
          x, y = x - upX * snapH * ts, y - upY * snapH * ts
        end
        k = k + 1
        local col = colAt(cols, k)
        col.other, col.type, col.t, col.nx, col.ny = hit.body, hit.pick, hit.t, hit.nx, hit.ny
        col.touchX, col.touchY, col.x, col.y, col.overlapping = x, y, hit.x, hit.y, false
        hit.body, hit.pick = nil, nil
      end
    end
    leave(self, level)
    if cache then self._mover = 0 end
    level.filter, level.body, level.visited, level.sid = false, false, false, false
    hit.body, hit.pick = nil, nil -- (a move a filter ended with a hit in hand: nothing kept alive)
    local one1, one2 = level.one1, level.one2 -- (nor the one-leaf lists)
    if one1 then one1[1], one2[1] = nil, nil end
    for i = 1, k do visited[cols[i].other] = nil end
  end
  local spare = cols.spare
  for i = #cols, k + 1, -1 do -- (kept for a longer list later, without the body they named)
    local col = cols[i]
    col.other = false
    spare[#spare + 1] = col
    cols[i] = nil
  end
  return x, y, cols, k
end

return Space
