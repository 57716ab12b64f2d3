--- Allocation measurements shared by the specs: kilobytes counted with the GC stopped,
--- never seconds.
local alloc = {}

-- Locals, not globals: busted runs specs in an environment whose global lookups may
-- allocate, and the measuring window must hold only the calls being measured.
local collectgarbage, huge = collectgarbage, math.huge

local function run(fn, n)
  for _ = 1, n do fn() end
end

--- KB allocated by `n` calls of `fn`: the least of three windows, each with the GC stopped
--- and after a warm-up of `warmup` calls (default 2,000) through the same loop.
---@param fn function @param n integer @param warmup integer|nil
---@return number
function alloc.kbPer(fn, n, warmup)
  run(fn, warmup or 2000)
  local least = huge
  for _ = 1, 3 do
    collectgarbage('collect')
    collectgarbage('stop')
    run(fn, 100)
    local before = collectgarbage('count')
    run(fn, n)
    local used = collectgarbage('count') - before
    collectgarbage('restart')
    if used < least then least = used end
  end
  return least
end

--- "Allocates nothing" means no allocation per call. The smallest Lua allocation is 16
--- bytes or more, so one per call over 10,000 calls is at least 156 KB. A window may still
--- hold a one-time growth of the VM's own: under busted, Lua 5.2 shows the same ~3.2 KB
--- whether the window holds 1 call or 40,000, so the budget is under 4 KB per window.
alloc.ONE_TIME_KB = 4

--- Assert that `kb` (from kbPer over 10,000 calls) means no allocation per call.
---@param kb number @param what string
function alloc.nothingPerCall(kb, what)
  assert(kb < alloc.ONE_TIME_KB, ('%s allocated %.3f KB over 10,000 calls'):format(what, kb))
end

--- On LuaJIT the measurements run interpreted: the trace compiler allocates its own
--- bookkeeping whenever it compiles a new side trace, which can happen at any moment, while
--- the interpreter shows the program's allocations exactly (compiled code can only sink
--- allocations, never add any). bench/ reports garbage with the JIT on. Call these from a
--- describe block's setup and teardown. jit.off() stops new traces only: traces compiled by
--- earlier specs keep running, and now and then one allocated in a window (a hierarchical
--- grid frame showed 9-48 KB in 2 runs of 12, 0 in 12 with the traces flushed), so they are
--- flushed too.
local jit = rawget(_G, 'jit')
function alloc.jitOff()
  if jit then
    jit.off()
    jit.flush()
  end
end
--- See alloc.jitOff.
function alloc.jitOn() if jit then jit.on() end end

return alloc
