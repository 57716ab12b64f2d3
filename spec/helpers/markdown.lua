--- Reading the project's markdown (README.md, docs/, examples/) for the documentation specs:
--- its fenced code blocks with their doc-test markers (spec/docs_examples_spec.lua), its
--- headings as GitHub names their anchors, and its links (spec/docs_links_spec.lua).
---
--- Doc-test markers: an HTML comment on the line just above a ```lua fence (blank lines
--- between are allowed), invisible on the rendered page:
---   <!-- doc-test: continue -->        the block goes on from the previous ```lua block of the
---                                      same file: the two run as one chunk
---   <!-- doc-test: skip: REASON -->    the block is not run; REASON says why
--- Any other `<!-- doc-test: ... -->` is an error, as is a marker that no ```lua fence follows.
local M = {}

--- The markdown files the specs read: README.md, then every .md under docs/ and examples/,
--- sorted (the list comes from `find`, run by the spec, never by strike).
---@return string[]
function M.files()
  local list = { 'README.md' }
  local p = assert(io.popen('find docs examples -name "*.md" 2>/dev/null | LC_ALL=C sort'))
  for line in p:lines() do list[#list + 1] = line end
  p:close()
  return list
end

---@param path string
---@return string
function M.read(path)
  local f = assert(io.open(path, 'rb'))
  local s = f:read('*a')
  f:close()
  return s
end

-- The lines of a text (without their newlines).
local function lines(text)
  local out = {}
  for line in (text:gsub('\r\n', '\n') .. '\n'):gmatch('(.-)\n') do out[#out + 1] = line end
  return out
end
M.lines = lines

--- The fenced code blocks of a text, and what is wrong with its fences and markers.
--- Each block: { lang =, line = (the opening fence's line), code = (its lines joined),
--- marker = nil | { kind = 'continue' | 'skip', reason =, line = } }.
---@param text string
---@return table[] blocks
---@return string[] problems
function M.blocks(text)
  local blocks, problems = {}, {}
  local open, pending = nil, nil
  local function orphan(m)
    problems[#problems + 1] = ('line %d: a doc-test marker with no block after it'):format(m.line)
  end
  for n, line in ipairs(lines(text)) do
    if open then
      if line:match('^' .. open.fence .. '%s*$') then
        open.code = table.concat(open.body, '\n')
        open.body, open.fence = nil, nil
        blocks[#blocks + 1] = open
        open = nil
      else
        open.body[#open.body + 1] = line
      end
    else
      local fence, info = line:match('^(```+)%s*(.-)%s*$')
      if not fence then fence, info = line:match('^(~~~+)%s*(.-)%s*$') end
      local kind, rest = line:match('^%s*<!%-%-%s*doc%-test:%s*(%a+)(.-)%-%->%s*$')
      if fence then
        if info == '' then problems[#problems + 1] = ('line %d: a code block without a language'):format(n) end
        local lang = info:match('^(%S*)')
        open = { lang = lang, line = n, body = {}, fence = fence, marker = pending }
        if pending and lang ~= 'lua' then
          problems[#problems + 1] = ('line %d: a doc-test marker above a %s block, not a lua one'):format(pending.line,
            lang == '' and 'plain' or lang)
        end
        pending = nil
      elseif kind then
        if pending then orphan(pending) end
        if kind == 'continue' and rest:match('^%s*$') then
          pending = { kind = 'continue', line = n }
        elseif kind == 'skip' and rest:match('^:%s*%S') then
          pending = { kind = 'skip', reason = rest:match('^:%s*(.-)%s*$'), line = n }
        else
          problems[#problems + 1] = ('line %d: not a doc-test marker: %s (continue, or skip: REASON)'):format(n, line)
        end
      elseif line:gsub('`[^`]*`', ''):find('<!--%s*doc%-test') then -- (not a mention in inline code)
        problems[#problems + 1] = ('line %d: not a doc-test marker: %s'):format(n, line)
      elseif pending and not line:match('^%s*$') then
        orphan(pending)
        pending = nil
      end
    end
  end
  if open then problems[#problems + 1] = ('line %d: a code block that is never closed'):format(open.line) end
  if pending then orphan(pending) end
  return blocks, problems
end

-- UTF-8 characters of s, each as a string.
local function chars(s)
  local out = {}
  for c in s:gmatch('[%z\1-\127\194-\244][\128-\191]*') do out[#out + 1] = c end
  return out
end

--- The anchor GitHub gives a heading: its text in lower case, without anything but letters,
--- digits, `_`, `-` and spaces, each space a `-` (github-slugger's rule). Letters beyond
--- ASCII: those of Latin-1 (À-ÿ, lower-cased; not × and ÷) and the scripts from Greek to
--- U+1FFF are kept; punctuation and symbols (U+00A0-U+00BF, U+2000 and above) are dropped.
--- Inline code's backquotes and emphasis marks go as punctuation; a link keeps its text.
---@param heading string
---@return string
function M.slug(heading)
  heading = heading:gsub('%[([^%]]*)%]%([^%)]*%)', '%1')
  local out = {}
  for _, c in ipairs(chars(heading)) do
    if #c == 1 then
      local l = c:lower()
      if l:match('[%w_%- ]') then out[#out + 1] = l == ' ' and '-' or l end
    else
      local b1, b2 = c:byte(1, 2)
      local cp = #c == 2 and (b1 - 0xC0) * 64 + (b2 - 0x80) or nil
      if cp and cp >= 0xC0 and cp <= 0xFF and cp ~= 0xD7 and cp ~= 0xF7 then
        if cp <= 0xDE then c = string.char(b1, b2 + 0x20) end
        out[#out + 1] = c
      elseif cp and cp >= 0x370 then
        out[#out + 1] = c
      elseif #c == 3 and b1 == 0xE1 then -- U+1000-U+1FFF
        out[#out + 1] = c
      end
    end
  end
  return table.concat(out)
end

--- Every anchor of a text's headings (outside code blocks), as GitHub makes them: a heading
--- whose anchor came before gets `-1`, `-2`, ... Returns a set and the list in order.
---@param text string
---@return table set
---@return string[] list
function M.anchors(text)
  local set, list, seen = {}, {}, {}
  local fence
  for _, line in ipairs(lines(text)) do
    if fence then
      if line:match('^' .. fence .. '%s*$') then fence = nil end
    else
      fence = line:match('^(```+)') or line:match('^(~~~+)')
      local h = not fence and line:match('^#+%s+(.-)%s*#*%s*$')
      if h then
        local base = M.slug(h)
        local a = base
        if seen[base] then a = base .. '-' .. seen[base] end
        seen[base] = (seen[base] or 0) + 1
        set[a] = true
        list[#list + 1] = a
      end
    end
  end
  return set, list
end

--- The links of a text, outside code blocks and inline code: `[text](target)` and
--- `![alt](target)`, as { target =, line = }.
---@param text string
---@return table[]
function M.links(text)
  local out = {}
  local fence
  for n, line in ipairs(lines(text)) do
    if fence then
      if line:match('^' .. fence .. '%s*$') then fence = nil end
    else
      fence = line:match('^(```+)') or line:match('^(~~~+)')
      if not fence then
        local plain = line:gsub('``.-``', ''):gsub('`[^`]*`', '')
        for target in plain:gmatch('%]%(([^%)]*)%)') do out[#out + 1] = { target = target, line = n } end
        for target in plain:gmatch('^%s*%[[^%]]+%]:%s*(%S+)') do out[#out + 1] = { target = target, line = n } end
      end
    end
  end
  return out
end

return M
