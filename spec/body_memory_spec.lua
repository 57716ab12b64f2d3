-- A body's memory (docs/performance.md, "The space, side by side": Memory, bytes a body). Each
-- table a body is made of is allocated once at its final size: as small as a table holding its
-- numbers and its named fields can be on the VM running (measured here on a table built in one
-- go, the oracle), never grown later, when the body is added to a space, queried or collided;
-- and bodies of one size share their local geometry (spec/shared_geometry_spec.lua). This
-- counts bytes (collectgarbage 'count' after full collections), never seconds.
local S = require('strike')
local layout = require('strike.base.layout')

local H, T = S.hapes, S.trikers
local N = 2000
local load = loadstring or load -- luacheck: ignore 113
local tnew = require('strike.compat').tableNew
local alloc = require('spec.helpers.alloc')

local function fullGC()
  for _ = 1, 3 do collectgarbage('collect') end
end

-- Bytes per item that make(i) keeps, for i = 1..N (the list holding them made first).
local function bytesPer(make, keep)
  keep = keep or {}
  for i = 1, N do keep[i] = keep[i] or false end
  fullGC()
  local before = collectgarbage('count')
  for i = 1, N do keep[i] = make(i) end
  fullGC()
  return (collectgarbage('count') - before) * 1024 / N, keep
end

-- The oracle: bytes of a table of `slots` numbers and `fields` named fields, made in one go
-- (LuaJIT: table.new and then its fields; elsewhere one constructor), so at its smallest.
local function tableBytes(slots, fields)
  local make
  if tnew then
    make = function()
      local t = tnew(slots, fields)
      for k = 1, slots do t[k] = 0 end
      for f = 1, fields do t['f' .. f] = true end
      return t
    end
  else
    local parts = {}
    for f = 1, fields do parts[#parts + 1] = ('f%d = true'):format(f) end
    for _ = 1, slots do parts[#parts + 1] = '0' end
    make = assert(load('return function() return { ' .. table.concat(parts, ', ') .. ' } end'))()
  end
  return (bytesPer(make))
end

describe('a body\'s memory', function()
  setup(alloc.jitOff) -- (LuaJIT's traces are garbage-collected objects too: spec/helpers/alloc.lua)
  teardown(alloc.jitOn)
  it('a single-shape collider is its tables at their smallest, its local geometry shared', function()
    -- (a collider: its cache slots and 4 flags and its list; the list: slot 0 and its shape;
    -- the shape: a rectangle's slots and its named fields, its local geometry shared)
    local c = T.Rectangle(0, 0, 2, 2)
    local shape = c:unpack()
    local function named(t)
      local k = 0
      for key in pairs(t) do
        if type(key) ~= 'number' then k = k + 1 end
      end
      return k
    end
    local listBytes = bytesPer(function() return { [0] = true, true } end)
    local want = tableBytes(layout.CSIZE, named(c)) + listBytes + tableBytes(layout.size(4), named(shape))
    local got = bytesPer(function(i) return T.Rectangle(3 * i, 0, 2, 2) end)
    assert.is_true(got <= want + 1, ('%.1f bytes a collider, its smallest tables take %.1f'):format(got, want))
    -- each of another size: its own local geometry too, 16 numbers and its 2 sizes
    local geometry = tableBytes(4 * 4 + 2, 0)
    local each = bytesPer(function(i) return T.Rectangle(3 * i, 0, 2 + i / 1024, 2) end)
    assert.is_true(each <= want + geometry + 1,
      ('%.1f bytes a collider of its own size, its smallest tables take %.1f'):format(each, want + geometry))
  end)

  it('a body does not grow when it is added to a space, queried and collided', function()
    -- (a shape made for a single-shape collider has room for 4 named fields, a bare one for a
    -- space's: Shape._slots. A class that makes its instances itself, as a game's may, says
    -- nothing to Shape._slots about the shape after it)
    local Own = S.hapes.ConvexPolygon:extend()
    Own._alloc = function() return {} end
    function Own:new(x, y) Own.super.new(self, x, y, x + 1, y, x, y + 1) end
    S.hapes.SpecOwnAlloc = Own
    for _, make in ipairs({
      function(i) return T.Rectangle(3 * i, 0, 2, 2) end,
      function(i) return H.Rectangle(3 * i, 0, 2, 2) end,
      function(i) return T.Circle(3 * i, 0, 1) end,
      function(i) return T.RegularPolygon(3 * i, 0, 6, 1) end,
      function(i)
        local _ = T.SpecOwnAlloc(0, 0)
        return H.Rectangle(3 * i, 0, 2, 2)
      end,
    }) do
      local built, bodies = bytesPer(make)
      local space = S.pace()
      for i = 1, N do space:add(bodies[i]) end
      space:queryPoint(3, 0)
      bodies[1]:translate(2, 0) -- (into its neighbour: a colliding pair)
      local _, pairs = space:collisions({})
      assert.equals(1, pairs)
      for i = 1, N do space:remove(bodies[i]) end
      space = nil -- luacheck: ignore 311
      fullGC()
      -- (what letting them go frees: what they take now)
      local before = collectgarbage('count')
      for i = 1, N do bodies[i] = false end
      fullGC()
      local now = (before - collectgarbage('count')) * 1024 / N
      -- (a table that grew would have at least 4 hash nodes more, 96 bytes; a few KB that the
      -- VM or busted keep or let go of meanwhile are a byte or two a body)
      assert.is_true(now <= built + 4, ('%.1f bytes a body once used, %.1f built'):format(now, built))
      -- (and the bodies were let go of: a few KB of the space's own may stay after it)
      assert.is_true(now >= built - 4, ('%.1f bytes a body once used, %.1f built'):format(now, built))
    end
  end)
end)
