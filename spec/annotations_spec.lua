-- tools/annotations.lua: the LuaLS annotation check (`make annotations`) and its --fix
-- splitter, on small synthetic sources.
if not package.path:find('./?.lua', 1, true) then package.path = './?.lua;' .. package.path end
local A = require('tools.annotations')

-- Lines joined with newlines.
local function src(...)
  return table.concat({ ... }, '\n') .. '\n'
end

-- The problems of a source, as 'line: message' strings.
local function problems(source)
  local out = {}
  for _, p in ipairs(A.check(source, 'test.lua')) do out[#out + 1] = p.line .. ': ' .. p.message end
  return out
end

local function assertClean(source)
  assert.are.same({}, problems(source))
end

-- Exactly one problem, on `line`, whose message contains `text` (plain).
local function assertOne(source, line, text)
  local ps = A.check(source, 'test.lua')
  assert.are.equal(1, #ps, table.concat(problems(source), '\n'))
  assert.are.equal(line, ps[1].line)
  assert.is_truthy(ps[1].message:find(text, 1, true), ps[1].message)
end

describe('tools/annotations check', function()
  it('passes a public function with a doc line, every @param in order and @return', function()
    assertClean(src(
      'local M = {}',
      '--- Sum of a and b.',
      '---@param a number',
      '---@param b number the second one',
      '---@return number',
      'function M.add(a, b)',
      '  return a + b',
      'end',
      'return M'))
  end)

  it('counts public functions and aliases', function()
    local ps, stats = A.check(src(
      'local M = {}',
      '--- One.',
      'function M.one() end',
      '--- Two.',
      'function M.deep.er:two() end',
      'local function helper() end',
      '--- The helper.',
      'M.helper = helper'), 'test.lua')
    assert.are.same({}, ps)
    assert.are.same({ functions = 3, aliases = 1 }, stats)
  end)

  it('fails two tags on one line, and sees only the first @param there', function()
    local ps = A.check(src(
      'local M = {}',
      '--- Sum.',
      '---@param a number @param b number',
      '---@return number',
      'function M.add(a, b) return a + b end'), 'test.lua')
    assert.are.equal(2, #ps)
    assert.are.equal(3, ps[1].line)
    assert.is_truthy(ps[1].message:find('2 tags on one line (@param @param)', 1, true))
    assert.are.equal(5, ps[2].line)
    assert.is_truthy(ps[2].message:find('no ---@param line for b', 1, true))
  end)

  it('finds a second tag of any kind, and also after `--- @`', function()
    assertOne(src('---@param x number @return self', 'local x'), 1, '(@param @return)')
    assertOne(src('--- @class A @field n number', 'local x'), 1, '(@class @field)')
    assertOne(src('---@param x number\t@see other', 'local x'), 1, '(@param @see)')
  end)

  it('leaves @ that is not a second tag alone', function()
    assertClean(src(
      '---@param x string mail to a@b.org, or `@param` in backquotes, (@see) in brackets',
      '---@param y string @the old EmmyLua description marker; @params is no tag word',
      '---@return string @returned as-is: an @return: with a colon is not a tag',
      'local x'))
  end)

  it('fails a missing @param', function()
    assertOne(src(
      'local M = {}',
      '--- Sum.',
      '---@param a number',
      '---@return number',
      'function M.add(a, b, c) return a + b + c end'), 5, 'M.add(a, b, c): no ---@param line for b, c')
  end)

  it('fails a misnamed @param', function()
    local ps = problems(src(
      'local M = {}',
      '--- Sum.',
      '---@param a number',
      '---@param c number',
      'function M.add(a, b) end'))
    assert.are.same({
      '4: ---@param c: M.add(a, b) has no parameter `c` (parameters: a, b)',
      '5: M.add(a, b): no ---@param line for b',
    }, ps)
  end)

  it('fails misordered @param lines', function()
    assertOne(src(
      'local M = {}',
      '--- Sum.',
      '---@param b number',
      '---@param a number',
      'function M.add(a, b) end'), 5, '---@param lines in the order b, a; the parameters are a, b')
  end)

  it('fails a @param given twice', function()
    assertOne(src(
      'local M = {}',
      '--- Sum.',
      '---@param a number',
      '---@param a number',
      'function M.f(a) end'), 4, '---@param a is given twice')
  end)

  it('does not want self for : methods, and takes ... and name?', function()
    assertClean(src(
      'local C = {}',
      '--- Method.',
      '---@param x? number',
      '---@param ... any',
      'function C:m(x, ...) end',
      '--- Method with self spelled out, allowed.',
      '---@param self table',
      '---@param x number',
      'function C:n(x) end'))
    assertOne(src(
      'local C = {}',
      '--- Dot function: self is an ordinary parameter.',
      '---@param x number',
      'function C.m(self, x) end'), 4, 'no ---@param line for self')
  end)

  it('fails a missing @return only when the body returns a value', function()
    assertOne(src(
      'local M = {}',
      '--- Twice.',
      '---@param x number',
      'function M.twice(x)',
      '  if x then return x * 2 end',
      'end'), 4, 'M.twice(x) returns a value but has no ---@return line')
    assertClean(src(
      'local M = {}',
      '--- Nothing back.',
      '---@param x number',
      'function M.f(x)',
      '  if x then return end',
      '  if x then return; end',
      '  repeat return until true',
      '  if x then return else return end',
      'end'))
  end)

  it('does not count a nested function\'s return', function()
    assertClean(src(
      'local M = {}',
      '--- Calls back.',
      '---@param t table',
      'function M.each(t)',
      '  local function inner() return 1 end',
      '  t.f = function() return 2 end',
      '  table.sort(t, function(a, b) return a < b end)',
      '  inner()',
      'end'))
    assertOne(src(
      'local M = {}',
      '--- Makes a function.',
      'function M.make()',
      '  return function() end',
      'end'), 3, 'M.make() returns a value')
  end)

  it('fails a public function without a doc comment directly above', function()
    assertOne(src(
      'local M = {}',
      'function M.add(a, b) return a + b end'), 2,
      'public function M.add(a, b) has no --- doc comment directly above (needs ---@param a, b and ---@return)')
    assertOne(src(
      'local M = {}',
      '--- Separated by a blank line.',
      '',
      'function M.f() end'), 4, 'has no --- doc comment')
    assertOne(src(
      'local M = {}',
      '--- Separated by a plain comment.',
      '-- luacheck: ignore',
      'function M.f() end'), 4, 'has no --- doc comment')
    assertOne(src(
      'local M = {}',
      '----------',
      'function M.f() end'), 3, 'has no --- doc comment')
  end)

  it('checks `A.b = function` like `function A.b`', function()
    assertOne(src(
      'local M = {}',
      '--- Sum.',
      '---@param a number',
      '---@return number',
      'M.add = function(a, b) return a + b end'), 5, 'no ---@param line for b')
  end)

  it('ignores local functions, globals, functions inside functions and _private ones', function()
    assertClean(src(
      'local M = {}',
      'local function helper(a) return a end',
      'local other = function(b) return b end',
      'function global(c) return c end',
      'function M._private(d) return d end',
      'function M.a.b:_alsoPrivate(e) return e end',
      '--- Public, and makes methods that are not.',
      '---@return table',
      'function M.make()',
      '  local C = {}',
      '  function C:method(f) return f end',
      '  C.field = function(g) return g end',
      '  return C',
      'end',
      'return helper, other'))
  end)

  it('is not confused by function/end in strings, long strings and comments', function()
    assertClean(src(
      'local M = {}',
      'local s = "function end \\" if do"',
      "local t = 'function \\' end'",
      'local u = [[ function x() end',
      '  end end if ]]',
      'local v = [==[ ]] function end ]=] ]==]',
      '-- function f() do',
      '--[[ function',
      '  if then ]]',
      '--[=[ end ]] end ]=]',
      '--- Doc.',
      '---@return string',
      'function M.f()',
      '  local w = [[',
      'end',
      ']] return w',
      'end',
      'local x = 1 --[[ inline ]] + 2',
      'local y = "a\\',
      'end function" .. "\\z',
      '   end"',
      '--- After all that, still the top level.',
      '---@param a number',
      'function M.g(a) end',
      'return s, t, u, v, x, y'))
    assertOne(src(
      'local M = {}',
      'local s = "end end"',
      'function M.g(a) end'), 3, 'public function M.g(a)')
  end)

  it('tracks blocks: while/for/if/repeat inside and around functions', function()
    assertClean(src(
      'local M = {}',
      'for i = 1, 2 do while false do end end',
      'if true then',
      '  --- Still top level: inside an if, not a function.',
      '  ---@param x number',
      '  function M.f(x) end',
      'elseif false then else end',
      'repeat local y = 1 until y',
      'do',
      '  --- Inside do.',
      '  function M.g() end',
      'end'))
  end)

  it('reports a nesting it cannot follow', function()
    assertOne(src('local x = 1', 'end'), 2, '`end` closes no open block')
    assertOne(src('if x then'), 1, 'still open at the end of the file')
  end)

  it('checks that @param, @return and @type lines are well-formed', function()
    local ps = problems(src(
      '---@param',
      '---@param x',
      '---@param 1x number',
      '---@return',
      '---@type',
      '---@type fun(a: number): number',
      'local v'))
    assert.are.same({
      '1: ---@param has no parameter name',
      '2: ---@param x has no type',
      '3: ---@param names `1x`, which is not a parameter name',
      '4: ---@return has no type',
      '5: ---@type has no type',
    }, ps)
  end)

  describe('aliases', function()
    it('need a doc comment directly above', function()
      assertOne(src(
        'local M = {}',
        'local function f(a) return a end',
        'M.f = f'), 3, 'public alias M.f = f has no --- doc comment directly above')
      assertOne(src(
        'local Shape = require("Shape")',
        'local C = {}',
        'C.getRoot = Shape.getRoot'), 3, 'public alias C.getRoot = Shape.getRoot')
      assertClean(src(
        'local M = {}',
        'local function f(a) return a end',
        '--- Documented: no @param needed.',
        'M.f = f',
        'local g = f and f or f',
        '--- The other one.',
        '---@type fun(a: number): number',
        'M.g = g'))
    end)

    it('are not required for values, private names or longer expressions', function()
      assertClean(src(
        'local M = {}',
        'local Class = require("Class")',
        'local t = {}',
        'local n = 3',
        'local function f() end',
        'M.Class = Class',
        'M.t = t',
        'M.n = n',
        'M._f = f',
        'M.u = f or t',
        'M.v = f()',
        'M.w = f .. "x"',
        'M.x, M.y = f, f',
        'local z = M.f',
        'return M, z'))
    end)

    it('match the target\'s parameters when they have @param lines', function()
      assertOne(src(
        'local M = {}',
        'local function f(a, b) return a + b end',
        '--- Sum.',
        '---@param b number',
        '---@param a number',
        'M.f = f'), 6, '---@param lines in the order b, a; the parameters are a, b')
      assertClean(src(
        'local C = {}',
        '--- Area.',
        '---@param scale number',
        '---@return number',
        'function C:area(scale) return scale end',
        '--- Same thing.',
        '---@param scale number',
        'C.size = C.area'))
    end)
  end)
end)

describe('tools/annotations command line', function()
  local path, printed, errors
  local function out(line) printed[#printed + 1] = line end
  local function err(line) errors[#errors + 1] = line end
  before_each(function()
    path = os.tmpname()
    printed, errors = {}, {}
  end)
  after_each(function() os.remove(path) end)
  local function write(s)
    local f = assert(io.open(path, 'wb'))
    f:write(s)
    f:close()
  end
  local function read()
    local f = assert(io.open(path, 'rb'))
    local s = f:read('*a')
    f:close()
    return s
  end

  it('prints file:line: message and exits 1 on problems, 0 with a summary otherwise', function()
    write(src('local M = {}', '---@param a T @param b T', 'function M.f(a, b) end'))
    assert.are.equal(1, A.main({ path }, out, err))
    assert.are.same({
      path .. ':2: 2 tags on one line (@param @param): LuaLS reads only the first, one tag per line'
        .. ' (--fix splits it)',
      path .. ':3: M.f(a, b): no ---@param line for b',
      'annotations: 1 files, 1 public functions, 2 problems',
    }, printed)
    printed = {}
    assert.are.equal(0, A.main({ '--fix', path }, out, err))
    assert.are.same({
      path .. ': split 1 line(s)',
      'annotations: 1 files, 1 public functions, 0 problems',
    }, printed)
    assert.are.equal(src('local M = {}', '---@param a T', '---@param b T', 'function M.f(a, b) end'), read())
    assert.are.same({}, errors)
  end)

  it('exits 2 without files, with an unknown option or an unreadable file', function()
    assert.are.equal(2, A.main({}, out, err))
    assert.are.equal(2, A.main({ '--nope', path }, out, err))
    assert.are.equal(2, A.main({ path .. '.missing' }, out, err))
    assert.are.equal(3, #errors)
  end)
end)

describe('tools/annotations fix', function()
  it('splits lines with several tags, keeping indentation and descriptions', function()
    local fixed, n = A.fix(src(
      'local M = {}',
      '--- Sum. @param in prose is left alone here.',
      '---@param a number the first @param b number|nil the second, a@b.c',
      '---@param c number',
      '  --- @param d T   @return number @the sum  ',
      'function M.add(a, b, c, d) return a + b + c + d end'))
    assert.are.equal(2, n)
    assert.are.equal(src(
      'local M = {}',
      '--- Sum. @param in prose is left alone here.',
      '---@param a number the first',
      '---@param b number|nil the second, a@b.c',
      '---@param c number',
      '  --- @param d T',
      '  --- @return number @the sum',
      'function M.add(a, b, c, d) return a + b + c + d end'), fixed)
    assert.are.same({}, A.check(fixed, 'test.lua'))
    assert.are.equal(0, select(2, A.fix(fixed)))
  end)

  it('changes nothing else: strings, code comments, CRLF and a missing final newline', function()
    local s = 'local s = [[\n---@param a T @param b T\n]]\nlocal t = 1 ---@type number @type string\r\n'
      .. '---@param x T @param y T\r\nfunction s.f(x, y) end'
    local fixed, n = A.fix(s)
    assert.are.equal(1, n)
    assert.are.equal('local s = [[\n---@param a T @param b T\n]]\nlocal t = 1 ---@type number @type string\r\n'
      .. '---@param x T\r\n---@param y T\r\nfunction s.f(x, y) end', fixed)
  end)

  it('does not invent annotations', function()
    local s = src('local M = {}', 'function M.f(a) return a end')
    assert.are.equal(s, (A.fix(s)))
    assert.are.equal(0, select(2, A.fix(s)))
  end)
end)
