-- A real-client check of `ilc debug` and of the README's nvim-dap setup:
-- it loads the Lua block of README.md as a user would put it in their
-- config, then debugs examples/motor.il as the issue's scenario says
-- (breakpoint on `ADD 1`, line 22; launched with start=TRUE@3, 6 scans):
-- the stop in scan 3 with CR 0 of type INT, the flow-control virtual
-- text, `next` to line 23, and the end of the session.
--
-- From the repository root, with `ilc` on PATH and nvim-dap checked out
-- in NVIM_DAP (needs Neovim 0.10 or newer):
--   NVIM_DAP=~/src/nvim-dap nvim --headless -u NONE -c "luafile editors/nvim/try-dap.lua"
-- It prints what it saw and exits with status 1 if a check failed.
-- (Tried with a Neovim 0.12 build and nvim-dap 9e848e0.)

vim.opt.runtimepath:prepend(os.getenv("NVIM_DAP") or "nvim-dap")
vim.cmd("filetype on")
local failed = false
local function check(ok, what)
  io.stdout:write((ok and "ok   " or "FAIL ") .. what .. "\n")
  failed = failed or not ok
end

local readme = table.concat(vim.fn.readfile("README.md"), "\n")
local block = readme:match("```lua\n(.-)```")
check(block ~= nil, "README.md has an nvim-dap configuration")
assert(load(block, "README.md"))()

local dap = require("dap")
vim.cmd("edit examples/motor.il")
check(vim.bo.filetype == "il", "motor.il has the filetype the configuration is for")
vim.api.nvim_win_set_cursor(0, { 22, 0 })
dap.toggle_breakpoint()

local stops, ended = 0, false
dap.listeners.after.event_stopped["try-dap"] = function() stops = stops + 1 end
dap.listeners.after.event_terminated["try-dap"] = function() ended = true end
dap.run(dap.configurations.il[2])

local function frame() return dap.session() and dap.session().current_frame end
vim.wait(10000, function() return stops > 0 and frame() ~= nil end, 20)
check(frame() and frame().line == 22, "stopped on line 22")

local cr = {}
local s = dap.session()
s:request("scopes", { frameId = frame().id }, function(_, r)
  s:request("variables", { variablesReference = r.scopes[1].variablesReference }, function(_, v)
    for _, x in ipairs(v.variables) do cr[x.name] = { x.value, x.type } end
  end)
end)
vim.wait(5000, function() return cr.CR ~= nil end, 20)
check(cr.CR and cr.CR[1] == "0" and cr.CR[2] == "INT", "the current result is 0 of type INT")
check(cr.scan and cr.scan[1] == "3", "in scan 3")

local ns = vim.api.nvim_create_namespace("ilc-flow")
vim.wait(3000, function() return #vim.api.nvim_buf_get_extmarks(0, ns, 0, -1, {}) > 0 end, 20)
local flow = {}
for _, m in ipairs(vim.api.nvim_buf_get_extmarks(0, ns, 0, -1, { details = true })) do
  flow[m[2] + 1] = m[4].virt_text[1][1]
end
check(flow[21] == "CR = 0 : INT", "flow control shows the CR after line 21: " .. tostring(flow[21]))

dap.step_over()
vim.wait(5000, function() return stops > 1 and frame() and frame().line ~= 22 end, 20)
check(frame() and frame().line == 23, "next stops on line 23")
dap.continue()
vim.wait(10000, function() return ended end, 20)
check(ended, "the session ends with terminated")
vim.cmd(failed and "cquit 1" or "qa!")
