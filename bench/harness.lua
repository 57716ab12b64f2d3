--- What the bench scripts share (bench/move.lua, movers.lua, space.lua, broadphase.lua,
--- tiled.lua): LuaJIT's limits, a full collection, option lists, numbers and markdown tables.
--- Not part of strike.
local H = {}

--- LuaJIT's limits for a run: 'love' (the default: LÖVE 11.4's boot.lua raises them to
--- maxtrace 2000, maxrecord 8000, maxmcode 16384 KB, as a game runs) or 'stock' (the
--- standalone interpreter's own: 1,000 traces, 512 KB). Sets them and returns which; 'stock'
--- where there is no JIT.
---@param choice string|nil 'love', 'stock' or nil (love)
---@return string
function H.jitLimits(choice)
  if choice ~= nil and choice ~= 'love' and choice ~= 'stock' then error('--jit must be love or stock', 2) end
  if rawget(_G, 'jit') and choice ~= 'stock' then
    require('jit.opt').start('maxtrace=2000', 'maxrecord=8000', 'maxmcode=16384')
    return 'love'
  end
  return 'stock'
end

--- Collect all garbage (twice: finalizers run in the first).
function H.fullGC()
  collectgarbage('collect')
  collectgarbage('collect')
end

--- A comma-separated option's values, numbers as numbers.
---@param s string
---@return table
function H.list(s)
  local t = {}
  for v in s:gmatch('[^,]+') do t[#t + 1] = tonumber(v) or v end
  return t
end

--- x with d decimals (2 by default); '—' for nil, 'nan' for NaN.
---@param x number|nil
---@param d integer|nil
---@return string
function H.fmt(x, d)
  if x == nil then return '—' end
  if x ~= x then return 'nan' end
  return ('%.' .. (d or 2) .. 'f'):format(x)
end

--- Print a markdown table: its head, then each row (a list of cells), then a blank line.
---@param head string[]
---@param rows table[]
function H.tableOut(head, rows)
  print('| ' .. table.concat(head, ' | ') .. ' |')
  local sep = {}
  for i = 1, #head do sep[i] = '---' end
  print('|' .. table.concat(sep, '|') .. '|')
  for _, r in ipairs(rows) do print('| ' .. table.concat(r, ' | ') .. ' |') end
  print()
end

--- Load the peers found in $STRIKE_PEERS: for each { folder, name, adapter module } of `list`
--- that `wanted(name)` allows, the adapter, loaded from the checkout of that folder (a folder
--- with a README.md), is appended to `libs`; one missing or failing is noted in `skipped`, and
--- without STRIKE_PEERS, `hint` is.
---@param list table[]
---@param wanted fun(name: string): boolean
---@param libs table
---@param skipped string[]
---@param hint string
function H.peers(list, wanted, libs, skipped, hint)
  local peerDir = os.getenv('STRIKE_PEERS')
  if not peerDir or peerDir == '' then
    skipped[#skipped + 1] = hint
    return
  end
  for _, p in ipairs(list) do
    if wanted(p[2]) then
      local f = io.open(peerDir .. '/' .. p[1] .. '/README.md', 'r')
      if f then
        f:close()
        local okReq, adapter = pcall(require, p[3])
        local ok, err = false, adapter
        if okReq then ok, err = adapter.load(peerDir, p[1]) end
        if ok then libs[#libs + 1] = adapter else skipped[#skipped + 1] = p[2] .. ' (' .. tostring(err) .. ')' end
      else
        skipped[#skipped + 1] = p[2] .. ' (no ' .. peerDir .. '/' .. p[1] .. ')'
      end
    end
  end
end

return H
