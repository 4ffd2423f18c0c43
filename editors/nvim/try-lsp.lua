-- A real-client check of `ilc lsp` and of the guide's Neovim setup: it loads
-- the Lua block of docs/guide.md ("Neovim") as a user would put it in their
-- config, opens a copy of examples/motor.il with a misspelt variable, and
-- checks what Neovim's own LSP client gets: the diagnostic, its quick fix
-- applied, hover with the CR types, an inlay hint, semantic tokens, go to
-- definition and formatting.
--
-- From the repository root, with `ilc` on PATH (needs Neovim 0.10 or newer):
--   nvim --headless -u NONE -c "luafile editors/nvim/try-lsp.lua"
-- It prints what it saw and exits with status 1 if a check failed.
-- (Tried with a Neovim 0.12 build.)

local failed = false
local function check(ok, what)
  io.stdout:write((ok and "ok   " or "FAIL ") .. what .. "\n")
  failed = failed or not ok
end
local function finish()
  io.stdout:flush()
  vim.cmd((failed and "cquit 1") or "qall!")
end

local guide = table.concat(vim.fn.readfile("docs/guide.md"), "\n")
local block = guide:match("```lua\n(vim%.filetype%.add.-)```")
check(block ~= nil, "docs/guide.md has a Neovim LSP configuration")
if not block then finish() end
assert(load(block, "docs/guide.md"))()
vim.cmd("filetype on")

-- A project of one file in a temporary folder: motor.il with `start`
-- misspelt on line 14 and line 16 out of the formatter's layout.
local dir = vim.fn.tempname()
vim.fn.mkdir(dir, "p")
local lines = vim.fn.readfile("examples/motor.il")
check(lines[14] == "    LD   start" and lines[16] == "    ANDN stop", "examples/motor.il is as expected")
lines[14] = "    LD   strat"
lines[16] = "ANDN      stop"
vim.fn.writefile(lines, dir .. "/motor.il")
vim.cmd("edit " .. dir .. "/motor.il")
local buf = vim.api.nvim_get_current_buf()
check(vim.bo.filetype == "il", "motor.il has the filetype the configuration is for")

local function client()
  return vim.lsp.get_clients({ bufnr = buf, name = "ilc" })[1]
end
vim.wait(10000, function() return client() ~= nil end, 20)
check(client() ~= nil, "the configuration started `ilc lsp` for the buffer")
if not client() then finish() end

vim.wait(10000, function() return #vim.diagnostic.get(buf) > 0 end, 20)
local diags = vim.diagnostic.get(buf)
local d = diags[1]
check(#diags == 1 and d.lnum == 13 and d.col == 9 and d.message:find("strat", 1, true) ~= nil,
  "one diagnostic at 14:10 naming `strat`: " .. (d and (d.code or "") .. " " .. d.message or "none"))

-- The quick fix, as `:lua vim.lsp.buf.code_action()` would list it.
local function request(method, params)
  local r = client():request_sync(method, params, 5000, buf)
  return r and r.result
end
local pos = function(l, c) return { textDocument = { uri = vim.uri_from_bufnr(buf) }, position = { line = l, character = c } } end
local actions = request("textDocument/codeAction", {
  textDocument = { uri = vim.uri_from_bufnr(buf) },
  range = { start = { line = 13, character = 9 }, ["end"] = { line = 13, character = 14 } },
  context = { diagnostics = {} },
}) or {}
local fix
for _, a in ipairs(actions) do
  if a.title:find("start", 1, true) and a.edit then fix = a end
end
check(fix ~= nil, "a quick fix renames it to `start`: " .. (fix and fix.title or "none"))
if fix then
  vim.lsp.util.apply_workspace_edit(fix.edit, client().offset_encoding)
  check(vim.api.nvim_buf_get_lines(buf, 13, 14, false)[1] == "    LD   start", "the fix is applied to line 14")
  vim.wait(10000, function() return #vim.diagnostic.get(buf) == 0 end, 20)
  check(#vim.diagnostic.get(buf) == 0, "the diagnostic is cleared after the edit")
end

local hover = request("textDocument/hover", pos(21, 5))
local text = hover and hover.contents and (hover.contents.value or vim.inspect(hover.contents)) or ""
check(text:find("CR before: `INT`", 1, true) and text:find("CR after: `INT`", 1, true),
  "hover on `ADD 1` shows the CR before and after: " .. text:gsub("\n", " "):sub(1, 80))

local hints = request("textDocument/inlayHint", {
  textDocument = { uri = vim.uri_from_bufnr(buf) },
  range = { start = { line = 0, character = 0 }, ["end"] = { line = 25, character = 0 } },
}) or {}
local on22
for _, h in ipairs(hints) do
  local label = type(h.label) == "string" and h.label or (h.label[1] and h.label[1].value) or ""
  if h.position.line == 21 then on22 = label end
end
check(on22 and on22:find("INT", 1, true), "an inlay hint gives the CR type on line 22: " .. tostring(on22))

-- Semantic tokens, as Neovim highlights them: `edge` (line 18) is an FB instance.
vim.wait(5000, function()
  return #vim.lsp.semantic_tokens.get_at_pos(buf, 17, 10) > 0
end, 20)
local kinds = {}
for _, t in ipairs(vim.lsp.semantic_tokens.get_at_pos(buf, 17, 10) or {}) do kinds[#kinds + 1] = t.type end
check(vim.tbl_contains(kinds, "instance"), "semantic token of `edge` on line 18: " .. table.concat(kinds, ","))

local def = request("textDocument/definition", pos(20, 10))
def = def and (def[1] or def)
check(def and def.range and def.range.start.line == 8, "go to definition of `starts` (line 21) lands on line 9")

vim.lsp.buf.format({ bufnr = buf, async = false, timeout_ms = 5000 })
-- The operands start after the file's widest operator, JMPCN.
check(vim.api.nvim_buf_get_lines(buf, 15, 16, false)[1] == "    ANDN  stop",
  "formatting lays line 16 out: " .. vim.api.nvim_buf_get_lines(buf, 15, 16, false)[1])

vim.fn.delete(dir, "rf")
finish()
