// A 1,000,000-move job in the workbench: how long the page takes to show
// it and how long the page's main thread is blocked at most meanwhile
// (Chromium's long tasks). A measurement, not a test (docs/performance.md):
//
//   node web/e2e/big.mjs URL [MOVES]
import { chromium } from "playwright-core";

const [url, moves = "1000000"] = process.argv.slice(2);
const browser = await chromium.launch({
  executablePath: process.env.CHROMIUM || "/usr/bin/chromium", headless: true, args: ["--no-sandbox"],
});
try {
  const page = await browser.newPage({ viewport: { width: 1600, height: 900 } });
  await page.goto(url);
  await page.waitForSelector("#program .row", { timeout: 60000 });
  await page.evaluate(() => {
    window.longTasks = [];
    new PerformanceObserver((list) => {
      for (const e of list.getEntries()) window.longTasks.push(e.duration);
    }).observe({ type: "longtask" });
  });
  const before = await page.evaluate(() => window.workbench.updates);
  const started = Date.now();
  await page.evaluate((n) => {
    document.querySelector("#moves").value = n;
    const sel = document.querySelector("#toolpath");
    sel.value = [...sel.options].find((o) => o.value === "pattern:zigzag").value;
    sel.dispatchEvent(new Event("change"));
  }, moves);
  await page.waitForFunction((n) => window.workbench.updates > n, before, { timeout: 600000 });
  const shown = Date.now() - started;
  const info = await page.locator("#program-info").innerText();
  // Scroll to the end: the last line is drawn.
  const scrollStart = Date.now();
  await page.evaluate(() => { const p = document.querySelector("#program"); p.scrollTop = p.scrollHeight; });
  await page.waitForFunction(() => document.querySelector("#program .row:last-child")?.textContent.includes("M30"));
  const scrolled = Date.now() - scrollStart;
  const rows = await page.evaluate(() => document.querySelectorAll("#program .row").length);
  const tasks = await page.evaluate(() => window.longTasks);
  const serverMs = await page.evaluate(() => window.workbench.lastServerMs);
  console.log(`BIG ${JSON.stringify({
    moves: Number(moves), program: info, shown_ms: shown, server_ms: Math.round(serverMs),
    longest_block_ms: Math.round(Math.max(0, ...tasks)), blocks_over_50ms: tasks.length,
    scroll_to_end_ms: scrolled, rows_in_page: rows,
  })}`);
} finally {
  await browser.close();
}
