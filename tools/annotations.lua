--- tools/annotations.lua: checks that strike's public functions carry LuaLS (Lua language
--- server) annotations the language server can actually read, and mechanically splits
--- lines that carry several tags. Plain Lua 5.1-5.4 / LuaJIT, no dependencies.
---
--- Usage:
---   lua tools/annotations.lua [--fix] FILE...
---     prints `file:line: message` per problem and a one-line summary; exits 1 when there
---     is any problem, 0 otherwise (2 on a usage or I/O error). The caller lists the files
---     (the Makefile passes `find strike -name '*.lua'`); the tool scans no directories.
---     --fix first rewrites each file in place, splitting every doc line that carries
---     several tags (rule 1) into one tag per line, then checks the result.
---   require('tools.annotations').check(source, filename) -> problems, stats
---     problems: list of { line = n, message = '...' } (sorted by line); stats:
---     { functions = n, aliases = m } (public functions, of which m are aliases).
---   require('tools.annotations').fix(source) -> newSource, linesSplit
---
--- Terms.
---   Doc line: a line holding nothing but a short comment that starts with `---` (after
---   indentation), outside strings and long comments. A line made only of four or more
---   dashes is a separator, not a doc line.
---   Annotation line: a doc line of the form `---@tag ...` or `--- @tag ...` (LuaLS reads
---   both). LuaLS reads ONE tag per line: after the first tag's name and type, the rest of
---   the line is a description (a leading `@` there is the old EmmyLua description marker).
---   Doc block of line L: the consecutive doc lines directly above L (the line L - 1 must
---   be a doc line; a blank or plain `--` line ends the block).
---   Top level: not inside any function body. Nesting is tracked by a tokenizer that knows
---   quoted strings, long strings [[ ]] / [==[ ]==], short comments and --[[ ]] long
---   comments; `function`, `if`, `do` and `repeat` open a block, `end` and `until` close
---   one (`while` and `for` open theirs with their `do`).
---
--- Rules.
---   1. Two tags on one line. An annotation line must not contain a second tag: whitespace,
---      then `@` and one of the LuaLS tag words (TAGS below: param, return, field, type,
---      class, alias, ...), then whitespace or the end of the line. So `@` inside words or
---      addresses (a@b.c), after punctuation (`@param` in backquotes, '(@see x)'), or
---      followed by a word that is not a tag (`@the value`, the EmmyLua description marker)
---      is description text. `--fix` splits at exactly these places.
---   2. Well-formed tags, on every annotation line of the file (the first tag of a line, the
---      one LuaLS reads): `---@param NAME TYPE [description]` where NAME is an identifier or
---      `...`, optionally followed by `?`; `---@return TYPE ...` and `---@type TYPE` must
---      have a type.
---   3. Public functions. A public function is a top-level definition
---        function A.b(...)   function A:b(...)   function A.b.c:d(...)   A.b = function(...)
---      (a dotted or method name, any depth) whose last name part does not start with `_`.
---      `local function f`, `local f = function`, plain global `function f` and functions
---      inside other functions are not public. Each public function needs:
---      a. a doc block directly above it;
---      b. one `---@param NAME` line for each parameter, named as in the definition and in
---         the same order, and no @param for a name that is not a parameter. `self` is not
---         a parameter of a `:` method (a `---@param self` line there is allowed and
---         skipped); a vararg is `---@param ...`; `name?` counts as `name`;
---      c. at least one `---@return` line when its own body has a `return` followed by an
---         expression (not `return`, `return;` or `return end`); returns inside nested
---         functions do not count. A function that returns nothing needs no @return (one
---         that has @return anyway, e.g. an abstract method, is not flagged).
---   4. Public aliases. A top-level statement `A.b = X` or `A.b = X.y.z` whose right side is
---      only a name or a dotted name (nothing follows it in the expression), whose left
---      side is dotted and whose last part does not start with `_`, is an alias of a
---      function and public, unless X is a top-level local initialised with a require(...)
---      call, a table constructor or a literal (then it is a value such as a class or a
---      constant, not checked). An alias needs a doc block directly above it. @param lines
---      are not required; when present and the target is a function defined earlier in
---      the same file (`local function x`, `local x = function`, a top-level `function X.y`
---      or `X.y = function`, or an alias of one), they must name the target's parameters
---      in order, as in rule 3b. A target that is any other top-level local or a name from
---      elsewhere counts as a function too (e.g. `local f = jit and g or h`).
---      Aliases whose target is elsewhere (e.g. `Collider.getRoot = Shape.getRoot`) only
---      need the doc block (and rule 2 for any tags it has).
---   Lines a tokenizer cannot balance (an `end` with no open block, blocks still open at
---   the end of the file) are reported too: the other results would not be reliable.
local M = {}

--- The LuaLS tag words recognised as a second tag on a line (rule 1).
M.TAGS = {
  'alias', 'async', 'cast', 'class', 'deprecated', 'diagnostic', 'enum', 'field', 'generic',
  'meta', 'module', 'nodiscard', 'operator', 'overload', 'package', 'param', 'private',
  'protected', 'public', 'return', 'see', 'source', 'type', 'vararg', 'version',
}
local isTag = {}
for _, t in ipairs(M.TAGS) do isTag[t] = true end

local KEYWORDS = {}
for w in ([[and break do else elseif end false for function goto if in local nil not or
  repeat return then true until while]]):gmatch('%a+') do KEYWORDS[w] = true end

local OPS3 = { ['...'] = true }
local OPS2 = {
  ['=='] = true, ['~='] = true, ['<='] = true, ['>='] = true, ['..'] = true, ['::'] = true,
  ['//'] = true, ['<<'] = true, ['>>'] = true,
}

-- Count the newlines in src between positions i and j.
local function newlines(src, i, j)
  local n = 0
  for _ in src:sub(i, j):gmatch('\n') do n = n + 1 end
  return n
end

--- Split Lua source into tokens { type, value, line, endLine }. Types: 'name', 'keyword',
--- 'number', 'string', 'op', 'comment' (a short comment; value is its text from `--` to the
--- end of the line, without `\r`) and 'longcomment'. Never fails: an unterminated string or
--- long bracket runs to the end of the source.
---@param src string
---@return table[] tokens
local function tokenize(src)
  local toks = {}
  local i, n, line = 1, #src, 1
  if src:sub(1, 1) == '#' then -- a shebang line
    local e = src:find('\n', 1, true) or n + 1
    i = e
  end
  local function push(ty, value, startLine, endLine)
    toks[#toks + 1] = { type = ty, value = value, line = startLine, endLine = endLine or startLine }
  end
  -- A long bracket opening at position p (`[` then `=`* then `[`): returns the position
  -- after its closing bracket and the text between the brackets.
  local function longBracket(p)
    local eq = src:match('^%[(=*)%[', p)
    if not eq then return nil end
    local open = p + #eq + 2
    local close = ']' .. eq .. ']'
    local s, e = src:find(close, open, true)
    if not s then return n + 1, src:sub(open) end
    return e + 1, src:sub(open, s - 1)
  end
  while i <= n do
    local c = src:sub(i, i)
    if c == '\n' then
      line = line + 1
      i = i + 1
    elseif c:match('%s') then
      i = i + 1
    elseif c == '-' and src:sub(i + 1, i + 1) == '-' then
      local after, body = nil, nil
      if src:sub(i + 2, i + 2) == '[' then after, body = longBracket(i + 2) end
      if after then
        local nl = newlines(src, i, after - 1)
        push('longcomment', body, line, line + nl)
        line = line + nl
        i = after
      else
        local e = src:find('\n', i, true) or n + 1
        local text = src:sub(i, e - 1):gsub('\r$', '')
        push('comment', text, line)
        i = e
      end
    elseif c == '[' and src:match('^%[=*%[', i) then
      local after, body = longBracket(i)
      local nl = newlines(src, i, after - 1)
      push('string', body, line, line + nl)
      line = line + nl
      i = after
    elseif c == '"' or c == "'" then
      local j, startLine = i + 1, line
      while j <= n do
        local d = src:sub(j, j)
        if d == '\\' then
          -- an escape: `\` newline (or CR LF), `\z` and the blank space after it, or one char
          local e = src:match('^\r?\n()', j + 1) or src:match('^z%s*()', j + 1) or j + 2
          line = line + newlines(src, j, e - 1)
          j = e
        elseif d == c then
          break
        elseif d == '\n' then -- an unfinished string ends at the line's end
          break
        else
          j = j + 1
        end
      end
      push('string', src:sub(i + 1, j - 1), startLine, line)
      i = j + 1
      if src:sub(j, j) == '\n' then i = j end
    elseif c:match('[%a_]') then
      local w = src:match('^[%w_]+', i)
      push(KEYWORDS[w] and 'keyword' or 'name', w, line)
      i = i + #w
    elseif c:match('%d') or (c == '.' and src:sub(i + 1, i + 1):match('%d')) then
      local e
      if src:match('^0[xX]', i) then
        e = select(2, src:find('^0[xX][%x%.]*', i))
        e = select(2, src:find('^[pP][%+%-]?%d+', e + 1)) or e
      else
        e = select(2, src:find('^%d*%.?%d*', i))
        e = select(2, src:find('^[eE][%+%-]?%d+', e + 1)) or e
      end
      e = select(2, src:find('^[%w_]*', e + 1)) -- suffixes: LuaJIT's LL, ULL, i
      push('number', src:sub(i, e), line)
      i = e + 1
    else
      local op = src:sub(i, i + 2)
      if not OPS3[op] then
        op = src:sub(i, i + 1)
        if not OPS2[op] then op = c end
      end
      push('op', op, line)
      i = i + #op
    end
  end
  return toks
end

-- The full-line short comments of a token list: line -> comment text.
local function lineComments(toks)
  local byLine, prevEnd = {}, 0
  for _, t in ipairs(toks) do
    if t.type == 'comment' and t.line > prevEnd then byLine[t.line] = t.value end
    prevEnd = t.endLine
  end
  return byLine
end

-- Doc line: starts with `---`, and is not a separator made only of dashes.
local function isDocText(text)
  return text ~= nil and text:sub(1, 3) == '---' and not text:match('^%-%-%-%-+%s*$')
end

-- An annotation line's prefix (`---` plus any spaces), first tag word and the text after
-- the `@`; nil when the text is not an annotation line.
local function annotation(text)
  local prefix, rest = text:match('^(%-%-%-%s*)@(.*)$')
  if not prefix then return nil end
  return prefix, rest:match('^[%w_]*'), rest
end

-- The positions in `rest` (an annotation line after its first `@`) where a further tag
-- starts: each is the position of the whitespace run before `@tag`.
local function extraTags(rest)
  local found = {}
  for ws, tag, after in rest:gmatch('()%s+@([%w_]+)()') do
    local nextc = rest:sub(after, after)
    if isTag[tag] and (nextc == '' or nextc:match('%s')) then
      found[#found + 1] = { pos = ws, tag = tag }
    end
  end
  return found
end

-- Split one annotation line into one line per tag: a list of comment texts (without
-- indentation), or nil when it has a single tag.
local function splitLine(text)
  local prefix, _, rest = annotation(text)
  if not prefix then return nil end
  local extra = extraTags(rest)
  if #extra == 0 then return nil end
  local out, from = {}, 1
  for _, x in ipairs(extra) do
    out[#out + 1] = prefix .. '@' .. (rest:sub(from, x.pos - 1):gsub('%s+$', ''))
    from = rest:find('@', x.pos, true) + 1
  end
  out[#out + 1] = prefix .. '@' .. (rest:sub(from):gsub('%s+$', ''))
  return out
end

--- Rewrite `source` so that every doc line carrying several tags (rule 1) becomes one line
--- per tag, with the same indentation, comment prefix and descriptions. Nothing else
--- changes: no annotation is added or removed.
---@param source string
---@return string newSource
---@return integer linesSplit
function M.fix(source)
  local comments = lineComments(tokenize(source))
  local lines, pos = {}, 1
  while true do
    local e = source:find('\n', pos, true)
    if not e then lines[#lines + 1] = source:sub(pos); break end
    lines[#lines + 1] = source:sub(pos, e - 1)
    pos = e + 1
  end
  local split = 0
  for ln, text in pairs(comments) do
    local parts = isDocText(text) and splitLine(text)
    if parts then
      local l = lines[ln]
      local indent = l:match('^[ \t]*')
      local cr = l:sub(-1) == '\r' and '\r' or ''
      for k = 1, #parts do parts[k] = indent .. parts[k] .. cr end
      lines[ln] = table.concat(parts, '\n')
      split = split + 1
    end
  end
  return table.concat(lines, '\n'), split
end

-- Parameter name of a `---@param` annotation (rest = text after `@`): name, or nil and why.
local function paramName(rest)
  local name = rest:match('^param%s+(%S+)')
  if not name then return nil, 'has no parameter name' end
  local bare = name:gsub('%?$', '')
  if not (bare:match('^[%a_][%w_]*$') or bare == '...') then
    return nil, ('names `%s`, which is not a parameter name'):format(name)
  end
  if not rest:match('^param%s+%S+%s+%S') then return nil, ('%s has no type'):format(bare) end
  return bare
end

-- Walk the code tokens: public functions, aliases, top-level locals and definitions.
local function scan(code, add)
  local publicFns, aliases = {}, {}
  local locals, defined = {}, {} -- top level: local name -> info; dotted name -> function
  local chunk = { returnsValue = false }
  local stack, fnStack = {}, { chunk }

  local function at(k) return code[k] end
  local function isOp(t, v) return t ~= nil and t.type == 'op' and t.value == v end
  local function isKw(t, v) return t ~= nil and t.type == 'keyword' and t.value == v end

  -- A name chain Name { '.' Name } [ ':' Name ] starting at k: parts, seps, next index.
  local function chain(k, allowColon)
    if not (at(k) and at(k).type == 'name') then return nil end
    local parts, seps = { at(k).value }, {}
    k = k + 1
    while (isOp(at(k), '.') or (allowColon and isOp(at(k), ':'))) and at(k + 1) and at(k + 1).type == 'name' do
      seps[#seps + 1] = at(k).value
      parts[#parts + 1] = at(k + 1).value
      k = k + 2
      if seps[#seps] == ':' then break end
    end
    return parts, seps, k
  end
  local function joinChain(parts, seps)
    local s = parts[1]
    for k = 2, #parts do s = s .. seps[k - 1] .. parts[k] end
    return s
  end
  -- Where a statement can start: after nothing, `;`, a closing bracket, a value, or a
  -- keyword that ends a statement or opens a block.
  local function statementStart(prev)
    if prev == nil then return true end
    if prev.type == 'name' or prev.type == 'string' or prev.type == 'number' then return true end
    if prev.type == 'op' then
      return prev.value == ';' or prev.value == ')' or prev.value == ']' or prev.value == '}'
        or prev.value == '...'
    end
    local v = prev.value
    return v == 'end' or v == 'do' or v == 'then' or v == 'else' or v == 'repeat' or v == 'break'
      or v == 'true' or v == 'false' or v == 'nil'
  end
  -- Whether the token after a right-hand side name chain continues the expression.
  local function continues(t)
    if t == nil then return false end
    if t.type == 'name' then return false end
    if t.type == 'keyword' then return t.value == 'and' or t.value == 'or' end
    if t.type == 'op' then return t.value ~= ';' end
    return true -- a string or number right after: a call or a syntax error
  end

  local k = 1
  while k <= #code do
    local t = code[k]
    local prev = code[k - 1]
    local fnDepth = #fnStack - 1
    if t.type == 'keyword' and t.value == 'function' then
      local rec = { line = t.line, isMethod = false, returnsValue = false, kind = 'anonymous' }
      local j = k + 1
      if isKw(prev, 'local') then
        rec.kind, rec.name = 'local', at(j) and at(j).value
        j = j + 1
        if fnDepth == 0 and rec.name then locals[rec.name] = { kind = 'function', fn = rec } end
      elseif at(j) and at(j).type == 'name' then
        local parts, seps, nj = chain(j, true)
        rec.name = joinChain(parts, seps)
        rec.last = parts[#parts]
        rec.isMethod = seps[#seps] == ':'
        rec.kind = #parts > 1 and 'field' or 'global'
        j = nj
      elseif isOp(prev, '=') then
        -- `A.b = function`, `local x = function`, or another anonymous function
        local m = k - 2
        if at(m) and at(m).type == 'name' then
          while isOp(at(m - 1), '.') and at(m - 2) and at(m - 2).type == 'name' do m = m - 2 end
          local parts, seps = chain(m, false)
          local before = at(m - 1)
          if #parts == 1 and isKw(before, 'local') then
            rec.kind, rec.name = 'local', parts[1]
            if fnDepth == 0 then locals[parts[1]] = { kind = 'function', fn = rec } end
          elseif #parts > 1 and statementStart(before) then
            rec.kind, rec.name, rec.last = 'field', joinChain(parts, seps), parts[#parts]
            rec.line = at(m).line
          end
        end
      end
      rec.params = {}
      if isOp(at(j), '(') then
        j = j + 1
        while at(j) and not isOp(at(j), ')') do
          if at(j).type == 'name' or isOp(at(j), '...') then rec.params[#rec.params + 1] = at(j).value end
          j = j + 1
        end
      else
        add(t.line, 'cannot read the parameter list after `function`')
      end
      if rec.kind == 'field' and fnDepth == 0 then
        defined[(rec.name:gsub(':', '.'))] = rec
        if rec.last:sub(1, 1) ~= '_' then publicFns[#publicFns + 1] = rec end
      end
      stack[#stack + 1] = 'function'
      fnStack[#fnStack + 1] = rec
      k = j + 1
    else
      if t.type == 'keyword' then
        local v = t.value
        if v == 'if' or v == 'do' or v == 'repeat' then
          stack[#stack + 1] = v
        elseif v == 'end' or v == 'until' then
          local top = stack[#stack]
          if top == nil then
            add(t.line, ('`%s` closes no open block: cannot follow the nesting'):format(v))
          else
            if (v == 'until') ~= (top == 'repeat') then
              add(t.line, ('`%s` closes a `%s`: cannot follow the nesting'):format(v, top))
            end
            stack[#stack] = nil
            if top == 'function' then fnStack[#fnStack] = nil end
          end
        elseif v == 'return' then
          local nt = code[k + 1]
          local empty = nt == nil or isOp(nt, ';')
            or (nt.type == 'keyword' and (nt.value == 'end' or nt.value == 'else'
              or nt.value == 'elseif' or nt.value == 'until'))
          if not empty then fnStack[#fnStack].returnsValue = true end
        elseif v == 'local' and fnDepth == 0 and at(k + 1) and at(k + 1).type == 'name' then
          -- top-level locals: what they hold, as far as aliases need to know
          local names, j = {}, k + 1
          while at(j) and at(j).type == 'name' do
            names[#names + 1] = at(j).value
            j = j + 1
            if isOp(at(j), '<') and isOp(at(j + 2), '>') then j = j + 3 end -- <const>, <close>
            if isOp(at(j), ',') then j = j + 1 else break end
          end
          local kind = 'other'
          if #names == 1 and isOp(at(j), '=') then
            local r = at(j + 1)
            if r and (r.type == 'string' or r.type == 'number' or isOp(r, '{')
                or isKw(r, 'nil') or isKw(r, 'true') or isKw(r, 'false')) then
              kind = 'value'
            elseif r and r.type == 'name' and r.value == 'require' then
              kind = 'value'
            end
          end
          for _, name in ipairs(names) do locals[name] = { kind = kind } end
        end
      elseif t.type == 'name' and fnDepth == 0 and statementStart(prev) then
        -- a top-level `A.b = X` or `A.b = X.y` alias
        local parts, seps, j = chain(k, false)
        if #parts > 1 and isOp(at(j), '=') and at(j + 1) and at(j + 1).type == 'name' then
          local rparts, rseps, rj = chain(j + 1, false)
          if not continues(at(rj)) then
            local target = joinChain(rparts, rseps)
            local info = #rparts == 1 and locals[target] or nil
            local fn = defined[target] or (info and info.fn)
            if not (info and info.kind == 'value') then
              local a = {
                line = t.line, name = joinChain(parts, seps), last = parts[#parts], target = target,
                fn = fn,
              }
              if fn then defined[a.name] = fn end
              if a.last:sub(1, 1) ~= '_' then aliases[#aliases + 1] = a end
            end
            k = rj - 1
          end
        end
      end
      k = k + 1
    end
  end
  if #stack > 0 then
    add(code[#code] and code[#code].endLine or 1,
      ('%d block(s) still open at the end of the file: cannot follow the nesting'):format(#stack))
  end
  return publicFns, aliases
end

-- The doc block directly above `line`: list of { line, text }, top to bottom.
local function docBlock(comments, line)
  local first = line
  while isDocText(comments[first - 1]) do first = first - 1 end
  local block = {}
  for l = first, line - 1 do block[#block + 1] = { line = l, text = comments[l] } end
  return block
end

-- Compare a doc block's @param lines with a parameter list (rule 3b).
local function checkParams(add, block, what, params, isMethod)
  local expected, pos = {}, {}
  for i, p in ipairs(params) do expected[i] = p; pos[p] = i end
  local got, seen = {}, {}
  for _, d in ipairs(block) do
    local _, tag, rest = annotation(d.text)
    if tag == 'param' then
      local name = paramName(rest)
      if name and not (isMethod and name == 'self') then
        if not pos[name] then
          add(d.line, ('---@param %s: %s has no parameter `%s` (parameters: %s)'):format(
            name, what, name, #params > 0 and table.concat(params, ', ') or 'none'))
        elseif seen[name] then
          add(d.line, ('---@param %s is given twice for %s'):format(name, what))
        else
          seen[name] = true
          got[#got + 1] = name
        end
      end
    end
  end
  local missing = {}
  for _, p in ipairs(expected) do
    if not seen[p] then missing[#missing + 1] = p end
  end
  if #missing > 0 then
    add(nil, ('%s: no ---@param line for %s'):format(what, table.concat(missing, ', ')))
  else
    for i = 1, #got do
      if got[i] ~= expected[i] then
        add(nil, ('%s: ---@param lines in the order %s; the parameters are %s'):format(
          what, table.concat(got, ', '), table.concat(expected, ', ')))
        break
      end
    end
  end
end

--- Check one file's text against the rules in this file's header.
---@param source string
---@param filename string|nil used only in messages about the file as a whole
---@return table[] problems { line = n, message = '...' }, sorted by line
---@return table stats { functions = n, aliases = m }
function M.check(source, filename)
  local problems, seq = {}, 0
  local function add(line, message)
    seq = seq + 1
    problems[#problems + 1] = { line = line, message = message, seq = seq, file = filename }
  end
  local toks = tokenize(source)
  local comments = lineComments(toks)

  -- Rules 1 and 2: every annotation line.
  local docLines = {}
  for ln, text in pairs(comments) do
    if isDocText(text) then docLines[#docLines + 1] = ln end
  end
  table.sort(docLines)
  for _, ln in ipairs(docLines) do
    local prefix, tag, rest = annotation(comments[ln])
    if prefix then
      local extra = extraTags(rest)
      if #extra > 0 then
        local tags = { '@' .. tag }
        for _, x in ipairs(extra) do tags[#tags + 1] = '@' .. x.tag end
        add(ln, ('%d tags on one line (%s): LuaLS reads only the first, one tag per line'
          .. ' (--fix splits it)'):format(#tags, table.concat(tags, ' ')))
      end
      if tag == 'param' then
        local name, why = paramName(rest)
        if not name then add(ln, '---@param ' .. why) end
      elseif tag == 'return' or tag == 'type' then
        if not rest:match('^[%w_]+%s+%S') then add(ln, ('---@%s has no type'):format(tag)) end
      end
    end
  end

  -- Rules 3 and 4.
  local code = {}
  for _, t in ipairs(toks) do
    if t.type ~= 'comment' and t.type ~= 'longcomment' then code[#code + 1] = t end
  end
  local publicFns, aliases = scan(code, add)
  for _, fn in ipairs(publicFns) do
    local function addHere(line, message) add(line or fn.line, message) end
    local block = docBlock(comments, fn.line)
    local what = ('%s(%s)'):format(fn.name, table.concat(fn.params, ', '))
    if #block == 0 then
      local needs = {}
      if #fn.params > 0 then needs[#needs + 1] = '---@param ' .. table.concat(fn.params, ', ') end
      if fn.returnsValue then needs[#needs + 1] = '---@return' end
      add(fn.line, ('public function %s has no --- doc comment directly above%s'):format(what,
        #needs > 0 and (' (needs ' .. table.concat(needs, ' and ') .. ')') or ''))
    else
      checkParams(addHere, block, what, fn.params, fn.isMethod)
      if fn.returnsValue then
        local has = false
        for _, d in ipairs(block) do
          if select(2, annotation(d.text)) == 'return' then has = true end
        end
        if not has then add(fn.line, ('%s returns a value but has no ---@return line'):format(what)) end
      end
    end
  end
  for _, a in ipairs(aliases) do
    local block = docBlock(comments, a.line)
    if #block == 0 then
      add(a.line, ('public alias %s = %s has no --- doc comment directly above'):format(a.name, a.target))
    elseif a.fn then
      local hasParam = false
      for _, d in ipairs(block) do
        if select(2, annotation(d.text)) == 'param' then hasParam = true end
      end
      if hasParam then
        checkParams(function(line, message) add(line or a.line, message) end, block,
          ('%s (= %s)'):format(a.name, a.target), a.fn.params, a.fn.isMethod)
      end
    end
  end

  table.sort(problems, function(p, q)
    if p.line ~= q.line then return p.line < q.line end
    return p.seq < q.seq
  end)
  for _, p in ipairs(problems) do p.seq = nil end
  return problems, { functions = #publicFns + #aliases, aliases = #aliases }
end

--- The public functions and aliases of one file's text (rules 3 and 4), with the doc block
--- directly above each, for tools/apidoc.lua: a list in line order of { name =, line =,
--- params =, isMethod =, target =, doc = } where name is as written (`A.b`, `A:b`), params
--- the parameter names (an alias's: its target's when the file defines it, else nil), target
--- the name an alias refers to (nil for a function) and doc the block's comment texts, top to
--- bottom, as written (`--- text`, `---@param ...`).
---@param source string
---@return table[]
function M.docs(source)
  local toks = tokenize(source)
  local comments = lineComments(toks)
  local code = {}
  for _, t in ipairs(toks) do
    if t.type ~= 'comment' and t.type ~= 'longcomment' then code[#code + 1] = t end
  end
  local publicFns, aliases = scan(code, function() end)
  local list = {}
  local function entry(line, name, params, isMethod, target)
    local doc = {}
    for _, d in ipairs(docBlock(comments, line)) do doc[#doc + 1] = d.text end
    list[#list + 1] = { name = name, line = line, params = params, isMethod = isMethod, target = target, doc = doc }
  end
  for _, fn in ipairs(publicFns) do entry(fn.line, fn.name, fn.params, fn.isMethod, nil) end
  for _, a in ipairs(aliases) do
    entry(a.line, a.name, a.fn and a.fn.params, a.fn and a.fn.isMethod or false, a.target)
  end
  table.sort(list, function(p, q) return p.line < q.line end)
  return list
end

--- A file's whole contents, or nil and the error (tools/apidoc.lua reads with it too).
---@param path string
---@return string|nil
---@return string|nil err
local function readFile(path)
  local f, err = io.open(path, 'rb')
  if not f then return nil, err end
  local s = f:read('*a')
  f:close()
  return s
end
M.readFile = readFile

local function writeFile(path, s)
  local f, err = io.open(path, 'wb')
  if not f then return nil, err end
  f:write(s)
  f:close()
  return true
end

--- The command line: see the header. Returns the exit status.
---@param argv string[]
---@param out fun(line: string)|nil where report lines go (default: print)
---@param err fun(line: string)|nil where errors go (default: standard error)
---@return integer
function M.main(argv, out, err)
  out = out or print
  err = err or function(line) io.stderr:write(line, '\n') end
  local fix, files = false, {}
  for _, a in ipairs(argv) do
    if a == '--fix' then
      fix = true
    elseif a == '-h' or a == '--help' or a:sub(1, 1) == '-' then
      err('usage: lua tools/annotations.lua [--fix] FILE...')
      return 2
    else
      files[#files + 1] = a
    end
  end
  if #files == 0 then
    err('usage: lua tools/annotations.lua [--fix] FILE...')
    return 2
  end
  local total, functions, status = 0, 0, 0
  for _, path in ipairs(files) do
    local src, rerr = readFile(path)
    if not src then
      err(('%s: cannot read: %s'):format(path, tostring(rerr)))
      status = 2
    else
      if fix then
        local fixed, n = M.fix(src)
        if n > 0 then
          local ok, werr = writeFile(path, fixed)
          if not ok then
            err(('%s: cannot write: %s'):format(path, tostring(werr)))
            status = 2
          else
            out(('%s: split %d line(s)'):format(path, n))
            src = fixed
          end
        end
      end
      local problems, stats = M.check(src, path)
      for _, p in ipairs(problems) do out(('%s:%d: %s'):format(path, p.line, p.message)) end
      total = total + #problems
      functions = functions + stats.functions
    end
  end
  out(('annotations: %d files, %d public functions, %d problems'):format(#files, functions, total))
  if status ~= 0 then return status end
  return total > 0 and 1 or 0
end

-- Run as a script (lua tools/annotations.lua ...): the chunk's arguments are the command
-- line's. When required, the first argument is the module name instead.
local first = ...
if type(arg) == 'table' and type(arg[0]) == 'string' and arg[0]:match('annotations%.lua$')
    and first == arg[1] then
  os.exit(M.main(arg))
end

return M
