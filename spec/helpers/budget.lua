--- How many random cases a property spec runs on this VM, and how (make test's time: every
--- VM runs every spec, and the random ones are most of the suite's time).
---
--- - All of them on LuaJIT, the VM LÖVE runs; a quarter (the same seed's first cases) on Lua
---   5.1, 5.2, 5.3 and 5.4, which are there to show that the same code gives the same answers
---   on them (integer division, number formats, the libraries), not to search further: every
---   case of a make test runs on LuaJIT, its first quarter on all five. STRIKE_FULL=1 runs all
---   of them on every VM.
--- - On LuaJIT, the first JIT_CASES cases of a loop run compiled and the rest interpreted:
---   the random cases of a property spec send the trace compiler down new paths at every
---   case, and it spends more time recording and aborting traces than it saves (the world
---   model: 10.5 s against 6.1 s with the compiler off; compound contacts 7.9 against 2.5).
---   The compiled cases check LuaJIT's compiled arithmetic, the rest its interpreter's; the
---   answers must be the same either way.
local budget = {}

local jit = rawget(_G, 'jit')
local full = os.getenv('STRIKE_FULL') == '1' or jit ~= nil

--- The share of the cases run on this VM (1 on LuaJIT, 0.25 on Lua 5.1-5.4).
budget.SHARE = full and 1 or 0.25

--- The cases of a loop that run compiled on LuaJIT.
budget.JIT_CASES = 30

--- The number of cases to run of `n`: n on LuaJIT, a quarter elsewhere (at least 1).
---@param n integer
---@return integer
function budget.cases(n)
  if full then return n end
  return math.max(1, math.ceil(n * budget.SHARE))
end

--- Run fn(case) for case = 1 .. budget.cases(n), LuaJIT's compiler on for the first
--- JIT_CASES only (and on again after, even when fn raises); returns the number run.
---@param n integer
---@param fn function
---@return integer
function budget.loop(n, fn)
  local count = budget.cases(n)
  local ok, err = pcall(function()
    for case = 1, count do
      if jit and case == budget.JIT_CASES + 1 then jit.off() end
      fn(case)
    end
  end)
  if jit then jit.on() end
  if not ok then error(err, 0) end
  return count
end

return budget
