--- strike itself, through its public API.
local S = require('strike')
local W = require('bench.workloads')

local A = { name = 'strike' }

local out = S.MTV()

local function collider(d)
  if d.kind == 'compound' then
    local c = S.trikers.Collider()
    for _, p in ipairs(d.parts) do c:add(W.strikeShape(p)) end
    return c
  end
  return S.trikers.Collider(W.strikeShape(d))
end

--- Methods: each builds its objects from a description and tests a pair, returning
--- hit (boolean) and the length of the separation vector (0 when no hit).
A.methods = {
  {
    name = 'S.AT',
    build = function(d) if d.kind ~= 'compound' then return W.strikeShape(d) end end,
    test = function(a, b)
      local m = S.AT(a, b, out)
      if m.separating then return false, 0 end
      return true, m.depth
    end,
  },
  {
    name = 'S.triking',
    build = collider,
    test = function(a, b)
      local m = S.triking(a, b, out)
      if not m then return false, 0 end
      return true, m.depth
    end,
  },
}

--- One frame of work on a body: move, turn, and read its bounds.
A.transform = {
  build = function(d) return W.strikeShape(d) end,
  step = function(s)
    s:translate(0.5, -0.25)
    s:rotate(0.01)
    return s:getBbox()
  end,
}

return A
