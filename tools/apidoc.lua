--- tools/apidoc.lua: docs/api.md, the API reference, generated from the LuaLS annotations
--- of strike/ (the doc blocks that `make annotations` checks: tools/annotations.lua finds
--- the public functions and their blocks). Plain Lua 5.1-5.4 / LuaJIT, no dependencies.
---
--- Usage:
---   lua tools/apidoc.lua --write docs/api.md FILE...    (`make api`)
---   lua tools/apidoc.lua --check docs/api.md FILE...    exit 1 when the file differs
---     FILE... are strike's sources (the Makefile passes `find strike -name '*.lua'`; the
---     tool scans no directories); they must be exactly the files SECTIONS lists below.
---   require('tools.apidoc').render(files, read) -> markdown text, or nil and the problems
---     (files: the paths; read(path) -> text).
---
--- What it writes, per public function (rule 3 of tools/annotations.lua) and public alias
--- (rule 4), in SECTIONS' order of files and each file's order of lines: a heading with the
--- name as the code defines it and its parameters, the first sentence of its doc block's
--- description (the doc lines before its first tag), a line per `---@param` (type and
--- description; `self` left out) and per `---@return`. A function whose block has no
--- description is a problem, and so is a file missing from SECTIONS: the tool then writes
--- nothing and lists them.
local A = require('tools.annotations')

local M = {}

--- The reference's parts, in order: a title, what the reader calls and how, and the files
--- whose public functions it lists. Every file of strike/ is in exactly one part.
M.SECTIONS = {
  {
    title = 'The module: S',
    intro = '`local S = require \'strike\'`. These are the functions a game calls on `S`;'
      .. ' `S.hapes.X(...)` and `S.trikers.X(...)` make shapes and colliders (below).',
    files = { 'strike/init.lua' },
  },
  {
    title = 'Shapes',
    intro = 'Every shape has the methods of `Shape` (and shapes made of vertices those of'
      .. ' `VertexShape`); a class may override one. Call them on a shape: `shape:translate(dx, dy)`.'
      .. ' `X:new(...)` is the constructor that `S.hapes.X(...)` runs.',
    files = {
      'strike/base/Shape.lua', 'strike/base/VertexShape.lua', 'strike/shapes/ConvexPolygon.lua',
      'strike/shapes/Rectangle.lua', 'strike/shapes/RegularPolygon.lua', 'strike/shapes/Ellipse.lua',
      'strike/shapes/Circle.lua', 'strike/shapes/Capsule.lua', 'strike/shapes/Edge.lua',
      'strike/shapes/Point.lua', 'strike/base/ChainSegment.lua',
    },
  },
  {
    title = 'Colliders',
    intro = 'Every collider has the methods of `Collider`. Call them on a collider:'
      .. ' `collider:add(shape)`. `X:new(...)` is the constructor that `S.trikers.X(...)` runs.',
    files = {
      'strike/colliders/Collider.lua', 'strike/colliders/single.lua', 'strike/colliders/Capsule.lua',
      'strike/colliders/Concave.lua', 'strike/colliders/Chain.lua',
    },
  },
  {
    title = 'The MTV',
    intro = 'What `S.AT` and `S.triking` return; `S.MTV(...)` makes one, to pass as `out`.',
    files = { 'strike/collide/MTV.lua' },
  },
  {
    title = 'The space',
    intro = '`S.pace()` makes one; call these on it: `space:add(body)`.',
    files = { 'strike/space/Space.lua', 'strike/space/motion.lua' },
  },
  {
    title = 'Tiled levels',
    intro = '`S.tiled(map, space)` returns a level; call these on it: `level:remove()`.',
    files = { 'strike/tiled/level.lua' },
  },
  {
    title = 'Classes',
    intro = 'The class helper every shape, collider and space is made with, and the registries'
      .. ' `S.hapes` and `S.trikers` (see [Extending](extending.md)).',
    files = { 'strike/class.lua', 'strike/registry.lua' },
  },
  {
    title = 'Internal modules',
    intro = 'What the functions above are built from. A game does not call these; they are'
      .. ' listed for readers of the code and for [extending](extending.md) strike with kinds'
      .. ' of its own (`strike/collide/dispatch.lua`).',
    files = {
      'strike/base/layout.lua', 'strike/check.lua', 'strike/compat.lua', 'strike/limits.lua',
      'strike/reserved.lua', 'strike/vec.lua', 'strike/draw.lua', 'strike/collide/args.lua',
      'strike/collide/dispatch.lua', 'strike/collide/kinds.lua', 'strike/collide/sat.lua',
      'strike/collide/rounded.lua', 'strike/collide/chain.lua', 'strike/collide/compound.lua',
      'strike/collide/outline.lua', 'strike/collide/contact.lua', 'strike/collide/ray.lua',
      'strike/motion/kernels.lua', 'strike/motion/sweep.lua', 'strike/motion/separation.lua',
      'strike/geometry/hull.lua', 'strike/geometry/polygon.lua', 'strike/geometry/decompose.lua',
      'strike/space/filter.lua', 'strike/space/tree.lua', 'strike/tiled/map.lua',
      'strike/tiled/shapes.lua', 'strike/tiled/merge.lua',
    },
  },
}

-- A doc line's text without its `---` and the one space after it.
local function strip(text)
  return (text:gsub('^%-%-%-', ''):gsub('^ ', ''))
end

-- Outside backquoted code spans, escape what markdown would read as markup: `<` (HTML),
-- `[` and `]` (links), `*` (emphasis).
local function escape(s)
  local out, i = {}, 1
  while i <= #s do
    local a = s:find('`', i, true)
    local b = a and s:find('`', a + 1, true)
    local plain = s:sub(i, (b and a - 1) or #s)
    out[#out + 1] = plain:gsub('[<%[%]%*]', function(c) return c == '<' and '&lt;' or '\\' .. c end)
    if not b then break end
    out[#out + 1] = s:sub(a, b)
    i = b + 1
  end
  return table.concat(out)
end

--- The first sentence of a text: up to the first `.` (outside brackets and code spans)
--- followed by the end or by white space and a capital letter, a backquote or a bracket.
---@param text string
---@return string
function M.firstSentence(text)
  local depth, code = 0, false
  for i = 1, #text do
    local c = text:sub(i, i)
    if c == '`' then
      code = not code
    elseif not code then
      if c == '(' or c == '[' or c == '{' then
        depth = depth + 1
      elseif (c == ')' or c == ']' or c == '}') and depth > 0 then
        depth = depth - 1
      elseif c == '.' and depth == 0 then
        local rest = text:sub(i + 1)
        if rest == '' or rest:match('^%s+[%u`%(]') then return text:sub(1, i) end
      end
    end
  end
  return text
end

-- A type at the start of s: a run up to white space outside brackets; a run that ends in
-- `,` or `:` goes on after the space (`number, number`, `fun(x: number): boolean`).
-- Returns the type and the rest.
local function splitType(s)
  local depth, i = 0, 1
  while i <= #s do
    local c = s:sub(i, i)
    if c == '(' or c == '<' or c == '{' or c == '[' then
      depth = depth + 1
    elseif (c == ')' or c == '>' or c == '}' or c == ']') and depth > 0 then
      depth = depth - 1
    elseif c:match('%s') and depth == 0 then
      local prev = s:sub(i - 1, i - 1)
      if prev ~= ',' and prev ~= ':' then break end
      local j = s:find('%S', i) or #s + 1
      i = j - 1
    end
    i = i + 1
  end
  return s:sub(1, i - 1), (s:sub(i):gsub('^%s+', ''))
end

-- Read a doc block: description text (the lines before the first tag) and the @param and
-- @return lines (a non-tag line after a tag continues its description).
local function readBlock(doc)
  local desc, params, returns = {}, {}, {}
  local last
  for _, text in ipairs(doc) do
    local body = strip(text)
    local tag, rest = body:match('^%s*@(%w+)%s*(.*)$')
    if tag == 'param' then
      local name, after = rest:match('^(%S+)%s*(.*)$')
      local ty, d = splitType(after or '')
      last = { name = (name or ''):gsub('%?$', ''), type = ty, desc = d }
      params[#params + 1] = last
    elseif tag == 'return' then
      local ty, d = splitType(rest)
      last = { type = ty, desc = d }
      returns[#returns + 1] = last
    elseif tag then
      last = nil
    elseif last then
      last.desc = (last.desc .. ' ' .. body:gsub('^%s+', '')):gsub('^ ', '')
    elseif #params == 0 and #returns == 0 then
      desc[#desc + 1] = body
    end
  end
  local text = table.concat(desc, ' '):gsub('%s+', ' '):gsub('^ ', ''):gsub(' $', '')
  return text, params, returns
end

-- The file's own description: the first sentence of its leading `---` lines.
local function fileSummary(src)
  local lines = {}
  for line in (src .. '\n'):gmatch('(.-)\r?\n') do
    if line:sub(1, 3) ~= '---' then break end
    local t = strip(line)
    if t:match('^%s*$') then break end
    lines[#lines + 1] = t
  end
  return M.firstSentence((table.concat(lines, ' '):gsub('%s+', ' ')))
end

-- A GitHub heading anchor (spec/docs_links_spec.lua computes them the same way).
local function anchor(title)
  return (title:lower():gsub('[^%w%- _]', ''):gsub(' ', '-'))
end

--- Render the reference from the given files (read through `read`).
---@param files string[]
---@param read fun(path: string): string
---@return string|nil markdown
---@return string[]|nil problems
function M.render(files, read)
  local problems, given, listed = {}, {}, {}
  for _, f in ipairs(files) do given[f] = true end
  for _, sec in ipairs(M.SECTIONS) do
    for _, f in ipairs(sec.files) do
      if listed[f] then problems[#problems + 1] = f .. ' is listed twice in SECTIONS' end
      listed[f] = true
      if not given[f] then
        problems[#problems + 1] = ('%s is in tools/apidoc.lua\'s SECTIONS but was not given (removed?)'):format(f)
      end
    end
  end
  for _, f in ipairs(files) do
    if not listed[f] then
      problems[#problems + 1] = ('%s: not in tools/apidoc.lua\'s SECTIONS (add it to a part)'):format(f)
    end
  end
  if #problems > 0 then return nil, problems end

  local out = {}
  local function w(s) out[#out + 1] = s or '' end
  w('# API reference')
  w()
  w('Every public function of `strike/`, with its parameters, what it returns and the first sentence')
  w('of its description, generated from the LuaLS annotations in the code by `tools/apidoc.lua`')
  w('(`make api` writes this file; `make test` fails when it is out of date: edit the annotations,')
  w('not this file). The [README](../README.md) and the guides say how the pieces fit together;')
  w('the annotations in the code give each function\'s full description.')
  w()
  local total = 0
  local bodies = {}
  for si, sec in ipairs(M.SECTIONS) do
    local part = {}
    local function p(s) part[#part + 1] = s or '' end
    p('## ' .. sec.title)
    p()
    p(sec.intro)
    for _, f in ipairs(sec.files) do
      local src = read(f)
      p()
      p(('### %s'):format(f))
      p()
      p(escape(fileSummary(src)))
      local entries = A.docs(src)
      if #entries == 0 then
        p()
        p('No public functions.')
      end
      for _, e in ipairs(entries) do
        local text, params, returns = readBlock(e.doc)
        if text == '' then
          problems[#problems + 1] = ('%s:%d: %s has no description before its tags'):format(f, e.line, e.name)
        end
        local names = {}
        if e.params then
          for _, n in ipairs(e.params) do names[#names + 1] = n end
        else
          for _, q in ipairs(params) do
            if q.name ~= 'self' then names[#names + 1] = q.name end
          end
        end
        p()
        p(('#### `%s(%s)`'):format(e.name, table.concat(names, ', ')))
        p()
        if e.target then p(('Alias of `%s`.'):format(e.target)) end
        p(escape(M.firstSentence(text)))
        local items = {}
        for _, q in ipairs(params) do
          if q.name ~= 'self' then
            items[#items + 1] = ('- `%s` (`%s`)%s'):format(q.name, q.type,
              q.desc ~= '' and (': ' .. escape(q.desc)) or '')
          end
        end
        for _, r in ipairs(returns) do
          items[#items + 1] = ('- returns `%s`%s'):format(r.type, r.desc ~= '' and (' ' .. escape(r.desc)) or '')
        end
        if #items > 0 then
          p()
          for _, it in ipairs(items) do p(it) end
        end
        total = total + 1
      end
    end
    bodies[si] = part
  end
  if #problems > 0 then return nil, problems end
  w(('%d functions, in these parts:'):format(total))
  w()
  for _, sec in ipairs(M.SECTIONS) do w(('- [%s](#%s)'):format(sec.title, anchor(sec.title))) end
  for _, part in ipairs(bodies) do
    w()
    for _, s in ipairs(part) do w(s) end
  end
  return table.concat(out, '\n') .. '\n'
end

local readFile = A.readFile

--- The command line (see the header). Returns the exit status.
---@param argv string[]
---@return integer
function M.main(argv)
  local mode, target = argv[1], argv[2]
  if (mode ~= '--write' and mode ~= '--check') or not target or not argv[3] then
    io.stderr:write('usage: lua tools/apidoc.lua --write|--check docs/api.md FILE...\n')
    return 2
  end
  local files = {}
  for i = 3, #argv do files[#files + 1] = argv[i] end
  local unreadable
  local text, problems = M.render(files, function(path)
    local s, err = readFile(path)
    if not s then unreadable = ('%s: cannot read: %s'):format(path, tostring(err)); return '' end
    return s
  end)
  if unreadable then io.stderr:write(unreadable, '\n'); return 2 end
  if not text then
    for _, p in ipairs(problems) do io.stderr:write(p, '\n') end
    io.stderr:write(('apidoc: %d problems, %s not written\n'):format(#problems, target))
    return 1
  end
  if mode == '--write' then
    local f, err = io.open(target, 'wb')
    if not f then io.stderr:write(('%s: cannot write: %s\n'):format(target, tostring(err))); return 2 end
    f:write(text)
    f:close()
    print(('apidoc: %s written'):format(target))
    return 0
  end
  local old = readFile(target)
  if old ~= text then
    io.stderr:write(('apidoc: %s is out of date: run `make api`\n'):format(target))
    return 1
  end
  print(('apidoc: %s is up to date'):format(target))
  return 0
end

-- Run as a script (lua tools/apidoc.lua ...); when required, the first argument is the
-- module name instead.
local first = ...
if type(arg) == 'table' and type(arg[0]) == 'string' and arg[0]:match('apidoc%.lua$') and first == arg[1] then
  os.exit(M.main(arg))
end

return M
