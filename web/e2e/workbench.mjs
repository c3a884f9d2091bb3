// The workbench end to end in a real browser: Playwright (playwright-core)
// driving Debian's Chromium headless. Run by tests/serve.rs, which starts
// `postc serve POST TOOLPATH` and passes its URL:
//
//   node web/e2e/workbench.mjs URL SCREENSHOT_DIR
//
// Steps (a screenshot after each, in SCREENSHOT_DIR): open the page with
// the post and the seed job; choose the corpus toolpath; see the program;
// introduce an error and see it underlined with its code; fix it with the
// quick fix; click an NC line and see the post line highlighted; convert
// to another dialect; measure edit-to-page latency; edit and save.
// Prints one `LATENCY {...}` JSON line; exits non-zero on any failure.
import { chromium } from "playwright-core";
import { mkdirSync } from "node:fs";
import { join } from "node:path";

const [url, shots = "target/workbench"] = process.argv.slice(2);
if (!url) {
  console.error("usage: node web/e2e/workbench.mjs URL [SCREENSHOT_DIR]");
  process.exit(2);
}
mkdirSync(shots, { recursive: true });
const executablePath = process.env.CHROMIUM || "/usr/bin/chromium";
const browser = await chromium.launch({ executablePath, headless: true, args: ["--no-sandbox"] });
const page = await browser.newPage({ viewport: { width: 1600, height: 900 } });
// A loaded CI machine: generous waits (each is a wait, not a timing).
page.setDefaultTimeout(60000);
page.on("pageerror", (e) => { console.error(`page error: ${e.message}`); process.exitCode = 1; });
const step = async (name) => {
  await page.screenshot({ path: join(shots, `${name}.png`) });
  console.log(`ok ${name}`);
};
const updates = () => page.evaluate(() => window.workbench.updates);
const nextUpdate = async (before) => page.waitForFunction((n) => window.workbench.updates > n, before);
const check = (ok, what) => { if (!ok) throw new Error(what); };

try {
  await page.goto(url);
  // 1. The page opens the given post and posts it over the given toolpath.
  await page.waitForSelector("#program .row");
  await step("01-open");

  // 2. A corpus toolpath from the picker, then the given one back.
  const corpusSeed = await page.evaluate(() =>
    [...document.querySelectorAll("#toolpath option")].map((o) => o.value).find((v) => v.includes("/corpus/toolpaths/arcs_mm.ron")));
  check(corpusSeed, "the picker lists the corpus toolpaths");
  let before = await updates();
  await page.selectOption("#toolpath", corpusSeed);
  await nextUpdate(before);
  const arcsLines = await page.evaluate(() => document.querySelector("#program-info").textContent);
  await step("02-corpus-toolpath");
  before = await updates();
  const given = await page.evaluate(() => document.querySelector("#toolpath optgroup[label=given] option").value);
  await page.selectOption("#toolpath", given);
  await nextUpdate(before);
  const program = await page.evaluate(() => document.querySelector("#program").innerText);
  check(/G21|G20/.test(program), `the program pane shows G-code: ${program.slice(0, 200)}`);
  console.log(`corpus toolpath arcs_mm.ron: ${arcsLines}`);

  // 3. An error: a misspelt section name, underlined with its code.
  check(await page.evaluate(() => window.workbench.find("RAPID_MOVE")), "the post has RAPID_MOVE");
  before = await updates();
  // One input event, so the page posts the whole word at once.
  await page.keyboard.insertText("RAPID_MOVX");
  await nextUpdate(before);
  await page.waitForSelector(".cm-lintRange-warning, .cm-lintRange-error");
  const range = page.locator(".cm-lintRange-warning, .cm-lintRange-error").first();
  await range.hover();
  const tooltip = page.locator(".cm-tooltip-lint");
  await tooltip.waitFor();
  const said = await tooltip.innerText();
  check(said.includes("PP017"), `the underline's tooltip names the code: ${said}`);
  await step("03-error-underlined");

  // 4. The quick fix, from the tooltip.
  before = await updates();
  await tooltip.locator("button", { hasText: "Replace" }).first().click();
  await nextUpdate(before);
  await page.waitForFunction(() => !document.querySelector(".cm-lintRange-warning, .cm-lintRange-error"));
  check((await page.evaluate(() => window.workbench.view.state.doc.toString())).includes("begin RAPID_MOVE"), "the fix restored the name");
  await step("04-fixed");

  // 5. An NC line: the post line that wrote it is highlighted.
  const row = page.locator("#program .row", { hasText: /^\d+G1[XYZF ]/ }).first();
  const ncLine = Number(await row.getAttribute("data-line"));
  await row.click();
  await page.waitForSelector(".cm-traced");
  const traced = await page.locator(".cm-traced").innerText();
  const trace = await page.locator("#trace").innerText();
  check(/post line \d+/.test(trace) && /toolpath event \d+/.test(trace), `the trace bar: ${trace}`);
  check(/FEED|\[F\]|G1|\[X\]/.test(traced), `the highlighted post line writes the move: ${traced}`);
  const tpShown = await page.locator("#trace-toolpath").innerText();
  check(/^toolpath line \d+: \S/.test(tpShown), `the toolpath line is shown: ${tpShown}`);
  console.log(`NC line ${ncLine} <- post line "${traced.trim()}" (${trace}) <- ${tpShown}`);
  await step("05-trace");

  // 6. Convert to another dialect, in the second pane.
  await page.selectOption("#target", "fusion");
  await page.click("#convert");
  await page.waitForFunction(() => document.querySelector("#convert-info").textContent !== "");
  const convertedText = await page.evaluate(() => window.workbench.converted.state.doc.toString());
  const info = await page.locator("#convert-info").innerText();
  check(info === "as .cps" && /^function onSection\(/m.test(convertedText), `converted: ${info} ${convertedText.slice(0, 200)}`);
  await step("06-converted");

  // 7. Latency: an edit re-posts the job and updates the page.
  const samples = [];
  const server = [];
  for (let i = 0; i < 12; i++) {
    // A comment line, typed at the end of the post's first line.
    await page.evaluate(() => {
      const v = window.workbench.view;
      const end = v.state.doc.line(1).to;
      v.dispatch({ selection: { anchor: end } });
      v.focus();
    });
    before = await updates();
    await page.keyboard.type(i % 2 ? "x" : "y");
    await nextUpdate(before);
    samples.push(await page.evaluate(() => window.workbench.lastLatency));
    server.push(await page.evaluate(() => window.workbench.lastServerMs));
  }
  const debounce = await page.evaluate(() => window.workbench.debounce);
  const sorted = [...samples].sort((a, b) => a - b);
  const median = sorted[Math.floor(sorted.length / 2)];
  const serverMedian = [...server].sort((a, b) => a - b)[Math.floor(server.length / 2)];
  const lines = await page.evaluate(() => window.workbench.view.state.doc.lines);
  console.log(`LATENCY ${JSON.stringify({
    post_lines: lines, samples: samples.length, debounce_ms: debounce,
    edit_to_page_ms: { median: +median.toFixed(1), min: +sorted[0].toFixed(1), max: +sorted[sorted.length - 1].toFixed(1) },
    after_debounce_ms: +(median - debounce).toFixed(1), server_ms_median: +serverMedian.toFixed(1),
  })}`);

  // 8. Save: an edit written back to the file.
  before = await updates();
  await page.evaluate(() => {
    const v = window.workbench.view;
    v.dispatch({ changes: { from: 0, insert: "+ saved by the workbench test\n" } });
  });
  await nextUpdate(before);
  await page.click("#save");
  await page.waitForFunction(() => document.querySelector("#save-status").textContent.startsWith("saved"));
  await step("07-saved");
} catch (e) {
  console.error(`failed: ${e.stack || e}`);
  await page.screenshot({ path: join(shots, "failure.png") }).catch(() => {});
  process.exitCode = 1;
} finally {
  await browser.close();
}
