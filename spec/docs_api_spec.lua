-- docs/api.md is what tools/apidoc.lua generates from the annotations of strike/ (`make api`):
-- a change to a public function's annotations, or a new public function, fails here until
-- the reference is generated again. The tool's own rules: its header.
local apidoc = require('tools.apidoc')
local read = require('spec.helpers.markdown').read

-- strike's sources, as the Makefile lists them (the spec runs `find`; strike never does).
local function sources()
  local list = {}
  local p = assert(io.popen('find strike -name "*.lua" | LC_ALL=C sort'))
  for line in p:lines() do list[#list + 1] = line end
  p:close()
  return list
end

-- The first line where two texts differ, for the failure message.
local function firstDifference(a, b)
  local n = 0
  local ia, ib = a:gmatch('([^\n]*)\n?'), b:gmatch('([^\n]*)\n?')
  while true do
    local la, lb = ia(), ib()
    n = n + 1
    if la ~= lb then return ('line %d: docs/api.md has %q, the annotations give %q'):format(n, tostring(la),
      tostring(lb)) end
    if la == nil then return nil end
  end
end

describe('docs/api.md', function()
  it('is what `make api` generates from the annotations', function()
    local files = sources()
    assert.is_true(#files >= 40, ('%d files under strike/'):format(#files))
    local text, problems = apidoc.render(files, read)
    assert.is_nil(problems and table.concat(problems, '\n'))
    local current = read('docs/api.md')
    if current ~= text then
      error('docs/api.md is out of date: run `make api` (' .. tostring(firstDifference(current, text)) .. ')', 0)
    end
  end)

  it('lists every public function the annotation check counts, each under its own heading', function()
    local A = require('tools.annotations')
    local total = 0
    for _, f in ipairs(sources()) do
      local _, stats = A.check(read(f), f)
      total = total + stats.functions
    end
    local api = read('docs/api.md')
    local headings = 0
    for _ in api:gmatch('\n#### `[^\n]+`\n') do headings = headings + 1 end
    assert.equals(total, headings)
    assert.matches(('\n%d functions, in these parts:'):format(total), api)
  end)
end)

describe('tools/apidoc.lua', function()
  local src = table.concat({
    'local M = {}',
    '--- Add two numbers. Then more text, which the reference leaves to the code.',
    '---@param a number the first',
    '---@param b number|nil the second (default 0)',
    '---@return number sum',
    'function M.add(a, b) return a + (b or 0) end',
    '---@param x number',
    'function M.bare(x) return x end',
    'return M',
  }, '\n')

  it('writes a heading, the first sentence, the parameters and the returns', function()
    local saved = apidoc.SECTIONS
    finally(function() apidoc.SECTIONS = saved end)
    apidoc.SECTIONS = { { title = 'Part', intro = 'Intro.', files = { 'x.lua' } } }
    local text, problems = apidoc.render({ 'x.lua' }, function()
      return (src:gsub('%-%-%-@param x number\nfunction M.bare%(x%) return x end\n', ''))
    end)
    assert.is_nil(problems)
    assert.matches('\n#### `M.add%(a, b%)`\n\nAdd two numbers%.\n\n', text)
    assert.matches('\n%- `a` %(`number`%): the first\n%- `b` %(`number|nil`%): the second %(default 0%)\n'
      .. '%- returns `number` sum\n', text)
    assert.is_nil(text:find('Then more text', 1, true))
  end)

  it('refuses a function without a description, and a file it does not place', function()
    local saved = apidoc.SECTIONS
    finally(function() apidoc.SECTIONS = saved end)
    apidoc.SECTIONS = { { title = 'Part', intro = 'Intro.', files = { 'x.lua' } } }
    local text, problems = apidoc.render({ 'x.lua' }, function() return src end)
    assert.is_nil(text)
    assert.same({ 'x.lua:8: M.bare has no description before its tags' }, problems)
    text, problems = apidoc.render({ 'x.lua', 'y.lua' }, function() return 'return {}' end)
    assert.is_nil(text)
    assert.matches('y.lua: not in tools/apidoc.lua\'s SECTIONS', problems[1])
  end)

  it('ends the first sentence at a full stop before a capital, not inside brackets or code', function()
    assert.equals('One (a. B).', apidoc.firstSentence('One (a. B). Two.'))
    assert.equals('Call `S.AT` first.', apidoc.firstSentence('Call `S.AT` first. Then S.ite.'))
    assert.equals('e.g. this and that.', apidoc.firstSentence('e.g. this and that.'))
  end)
end)
