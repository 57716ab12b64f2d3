--- The operation tables: what strike can do with one shape of a kind, and with a pair of
--- kinds. A shape's `kind` names its row ('polygon', 'circle', 'chain', or a kind a game
--- registers). Built-in kinds are registered in strike/collide/kinds.lua; a new kind needs
--- its own file of kernels and one registration (dispatch.registerKind, then
--- dispatch.register for each pair it supports).
---
--- Per kind, dispatch.kind[k]:
---   ray(s, ox, oy, ux, uy) -> lo, hi, nxLo, nyLo, nxHi, nyHi   (or nil: a miss)
---       the interval [lo, hi] of the line o + t u (u a unit vector) inside the shape (lo
---       may be negative, hi >= 0) and the outward unit normals at its two ends.
---   outline(g, s, mode), normals(g, s, len)   optional: how strike/draw.lua draws a shape
---       of the kind with love.graphics `g` (passed in: only draw.lua reads `love`); without
---       them it draws the shape's vertices as a polygon (two: a line) and a normal per edge.
---
--- Per ordered pair of kinds, dispatch.pair[ka][kb] (one table per pair):
---   collide(a, b, out) -> out
---       the narrow phase: fills the MTV-shaped `out` for (a, b) (see collide/sat.lua).
---   contact(a, b, nx, ny, depth, edge, out) -> count
---       the contact points of a colliding pair (see collide/contact.lua), from the MTV's
---       normal (from a toward b), depth and edgeIndex.
---   distance, toi   slots for the distance and time-of-impact queries; false until a
---       kernel is registered.
--- register(ka, kb, ops) fills both orders: (kb, ka) gets the same kernels with the
--- arguments swapped and the results turned around (the way Box2D's b2AddType registers
--- a pair once). A kernel written for (ka, kb) takes a last argument `flip`: when true it
--- must report the pair as (kb, ka). Contact kernels get the normal and edge turned, and
--- `flip` only for what depends on the order (the side in a contact id).
local dispatch = {}

--- Per-kind operations, dispatch.kind[kind].
dispatch.kind = {}
--- Per-pair operations, dispatch.pair[kindA][kindB].
dispatch.pair = {}
--- The collide kernels alone, dispatch.collide[kindA][kindB] (the same functions as
--- dispatch.pair[kindA][kindB].collide, one lookup fewer for the pair loops). A kind that is
--- not registered (a `_kind` a game changed: strike/reserved.lua) has an empty row, so that
--- the pair loops find no kernel, and say why, without a test of their own on the way.
dispatch.collide = setmetatable({}, { __index = function() return {} end })

-- The operations a pair table has, in order, and which need a kernel.
local PAIR_OPS = { 'collide', 'contact', 'distance', 'toi' }
local REQUIRED = { collide = true, contact = true }

local function row(ka)
  local r = dispatch.pair[ka]
  if not r then r = {}; dispatch.pair[ka] = r; dispatch.collide[ka] = {} end
  return r
end

--- Register what can be done with one shape of kind `k`.
---@param k string
---@param ops table { ray = function, outline = function|nil, normals = function|nil }
function dispatch.registerKind(k, ops)
  if type(k) ~= 'string' then error('dispatch.registerKind: the kind must be a string', 2) end
  if type(ops) ~= 'table' or type(ops.ray) ~= 'function' then
    error(('dispatch.registerKind: kind %q needs a ray function'):format(k), 2)
  end
  for _, name in ipairs({ 'outline', 'normals' }) do
    if ops[name] ~= nil and type(ops[name]) ~= 'function' then
      error(('dispatch.registerKind: kind %q: %s must be a function or nil'):format(k, name), 2)
    end
  end
  dispatch.kind[k] = ops
  row(k)
end

--- Register the kernels of the ordered pair (ka, kb); the pair (kb, ka) is filled in too.
---@param ka string
---@param kb string
---@param ops table { collide = function, contact = function, distance = function|nil, toi = function|nil }
function dispatch.register(ka, kb, ops)
  if not dispatch.kind[ka] or not dispatch.kind[kb] then
    error(('dispatch.register: register the kinds %q and %q first'):format(tostring(ka), tostring(kb)), 2)
  end
  local fwd = {}
  for _, name in ipairs(PAIR_OPS) do
    local f = ops[name]
    if f == nil or f == false then
      if REQUIRED[name] then error(('dispatch.register: (%s, %s) needs a %s kernel'):format(ka, kb, name), 2) end
      f = false
    elseif type(f) ~= 'function' then
      error(('dispatch.register: (%s, %s).%s must be a function'):format(ka, kb, name), 2)
    end
    fwd[name] = f
  end
  row(ka)[kb] = fwd
  dispatch.collide[ka][kb] = fwd.collide
  if ka == kb then return end
  local collide, contact = fwd.collide, fwd.contact
  local reversed = function(b, a, out) return collide(a, b, out, true) end
  dispatch.collide[kb][ka] = reversed
  row(kb)[ka] = {
    collide = reversed,
    contact = function(b, a, nx, ny, depth, edge, out) return contact(a, b, -nx, -ny, depth, -edge, out, true) end,
    distance = false,
    toi = false,
  }
end

return dispatch
