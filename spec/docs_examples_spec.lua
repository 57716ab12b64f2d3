-- Every ```lua block of the README and the guides (docs/, examples/) runs, so an example that
-- stops working fails the build. The conventions (spec/helpers/markdown.lua has the markers):
--  * each block runs on its own, in a fresh environment, with a stand-in for LÖVE as `love`
--    (spec/helpers/love.lua: it checks every draw call's arguments) and the repository's
--    root as the game's folder; `<!-- doc-test: continue -->` above a block makes it part
--    of the block before it: the two run as one chunk (the first one's locals are the
--    second's), with every line numbered as in the file;
--  * when the blocks have defined love.load, it runs; when they have defined love.update or
--    love.draw, 60 frames of 1/60 s follow (love.update, love.draw);
--  * `print(...) --> text` states what that print writes: the printed lines must be those
--    texts, in order (numbers compare as numbers: `10` and `10.0` are equal, and `0.33`
--    stands for any value that rounds to it at the digits shown; other words exactly);
--  * `<!-- doc-test: skip: REASON -->` leaves a block out; there are at most MAX_SKIPS,
--    each with its reason.
local md = require('spec.helpers.markdown')
local lovestub = require('spec.helpers.love')

local MAX_SKIPS = 3
local FRAMES = 60

-- Compile the blocks of a chain as one chunk with `env` as its globals: a block's locals
-- are there for the blocks that continue it, and every line keeps its number in `file`.
local function compile(chain, file, env)
  local parts, at = {}, 1
  for _, b in ipairs(chain) do
    parts[#parts + 1] = string.rep('\n', b.line - at + 1) .. b.code
    at = b.line + select(2, b.code:gsub('\n', '')) + 1
  end
  local src = table.concat(parts)
  local name = '@' .. file
  local setfenv = rawget(_G, 'setfenv')
  if setfenv then
    local fn, err = loadstring(src, name) -- luacheck: ignore 113 (Lua 5.1 and LuaJIT)
    if fn then setfenv(fn, env) end
    return fn, err
  end
  return load(src, name, 't', env)
end

-- The `--> text` a block's print lines promise, in order.
local function promised(code)
  local list = {}
  for line in (code .. '\n'):gmatch('(.-)\n') do
    local text = line:find('print(', 1, true) and line:match('%-%->%s?(.-)%s*$')
    if text then list[#list + 1] = text end
  end
  return list
end

-- Does the printed text match the promised one? Word by word; numbers as numbers, to the
-- digits the promise shows.
local function matches(got, want)
  local g, w = {}, {}
  for t in got:gmatch('%S+') do g[#g + 1] = t end
  for t in want:gmatch('%S+') do w[#w + 1] = t end
  if #g ~= #w then return false end
  for i = 1, #w do
    local a, b = tonumber(g[i]), tonumber(w[i])
    if a and b then
      local decimals = w[i]:match('^[-+]?%d*%.(%d+)$')
      local tol = decimals and 0.5 * 10 ^ -#decimals or 1e-9 * math.max(1, math.abs(b))
      if math.abs(a - b) > tol then return false end
    elseif g[i] ~= w[i] then
      return false
    end
  end
  return true
end

-- Run a chain of blocks (a block and the ones that continue it) in one environment.
local function runChain(file, chain)
  local fake = lovestub.new({ source = '.' })
  local printed = {}
  local env = setmetatable({
    love = fake.love,
    print = function(...)
      local parts = {}
      for i = 1, select('#', ...) do parts[i] = tostring((select(i, ...))) end
      printed[#printed + 1] = table.concat(parts, '\t')
    end,
  }, { __index = _G })
  rawset(_G, 'love', fake.love) -- (strike's drawing reads the global)
  finally(function() rawset(_G, 'love', nil) end)
  local L = fake.love
  local fn, err = compile(chain, file, env)
  assert(fn, ('%s:%d: the block does not compile: %s'):format(file, chain[1].line, tostring(err)))
  fn()
  if rawget(L, 'load') then L.load({}) end
  if rawget(L, 'update') or rawget(L, 'draw') then
    for _ = 1, FRAMES do
      if rawget(L, 'update') then L.update(1 / 60) end
      fake.draw()
    end
  end
  local want = {}
  for _, b in ipairs(chain) do
    for _, t in ipairs(promised(b.code)) do want[#want + 1] = t end
  end
  assert.equals(#want, #printed, ('%s:%d: %d lines printed, %d promised with -->:\n%s'):format(file, chain[1].line,
    #printed, #want, table.concat(printed, '\n')))
  for i = 1, #want do
    assert.is_true(matches(printed[i], want[i]), ('%s:%d: printed %q, the block says --> %s'):format(file,
      chain[1].line, printed[i], want[i]))
  end
end

local files = md.files()
local skips = {}

describe('the code blocks of the documentation', function()
  it('are found in the README and the guides', function()
    assert.is_true(#files >= 10, 'markdown files: ' .. table.concat(files, ', '))
  end)

  for _, file in ipairs(files) do
    local blocks, problems = md.blocks(md.read(file))
    describe(file, function()
      it('names each block\'s language and marks blocks as the doc-test conventions say', function()
        assert.are.same({}, problems)
      end)
      local chains = {}
      for _, b in ipairs(blocks) do
        if b.lang == 'lua' then
          if b.marker and b.marker.kind == 'skip' then
            skips[#skips + 1] = { file = file, line = b.line, reason = b.marker.reason }
          elseif b.marker and b.marker.kind == 'continue' then
            local last = chains[#chains]
            it(('line %d: continues a block'):format(b.line), function()
              assert.is_truthy(last, ('%s:%d: continues no block'):format(file, b.line))
            end)
            if last then last[#last + 1] = b end
          else
            chains[#chains + 1] = { b }
          end
        end
      end
      for _, chain in ipairs(chains) do
        local lastLine = chain[#chain].line
        local what = #chain > 1 and ('lines %d-%d (%d blocks)'):format(chain[1].line, lastLine, #chain)
          or ('line %d'):format(chain[1].line)
        it(what .. ' runs', function() runChain(file, chain) end)
      end
    end)
  end

  it(('leave at most %d blocks out, each with its reason'):format(MAX_SKIPS), function()
    local list = {}
    for _, s in ipairs(skips) do
      list[#list + 1] = ('%s:%d: %s'):format(s.file, s.line, s.reason)
      assert.is_true(#s.reason >= 20, ('%s:%d: a reason of a few words, got %q'):format(s.file, s.line, s.reason))
    end
    assert.is_true(#skips <= MAX_SKIPS, 'blocks left out:\n' .. table.concat(list, '\n'))
  end)
end)

describe('the doc-test conventions', function()
  it('compare printed numbers to the digits shown, words exactly', function()
    assert.is_true(matches('10.0', '10'))
    assert.is_true(matches('0.33333333', '0.33'))
    assert.is_false(matches('0.336', '0.33'))
    assert.is_false(matches('10.3', '10'))
    assert.is_true(matches('nil\t3', 'nil 3'))
    assert.is_false(matches('true', 'false'))
    assert.is_false(matches('1 2', '1'))
  end)

  it('read markers, and refuse a marker with no lua block after it', function()
    local blocks, problems = md.blocks(table.concat({
      '<!-- doc-test: skip: the reason -->', '```lua', 'x()', '```',
      '<!-- doc-test: continue -->', '', '```lua', 'y()', '```',
      '<!-- doc-test: continue -->', 'text', '```', 'plain', '```',
      '<!-- doc-test: run -->',
      'A mention, `<!-- doc-test: continue -->`, in inline code is no marker.',
    }, '\n'))
    assert.equals(3, #blocks)
    assert.same({ kind = 'skip', reason = 'the reason', line = 1 }, blocks[1].marker)
    assert.same({ kind = 'continue', line = 5 }, blocks[2].marker)
    assert.equals('y()', blocks[2].code)
    assert.same({ 'line 10: a doc-test marker with no block after it', 'line 12: a code block without a language',
      'line 15: not a doc-test marker: <!-- doc-test: run --> (continue, or skip: REASON)' }, problems)
  end)
end)
