// The post workbench's page (docs/workbench.md). Everything a post means
// comes from the server's JSON API (src/cli/serve/api.rs): this file only
// shows it — the editor, the program pane, the findings, the backplot,
// the converted post — and sends the editor's text back on every edit.
import { EditorState, StateEffect, StateField, Compartment } from "@codemirror/state";
import {
  EditorView, Decoration, keymap, lineNumbers, highlightActiveLine, highlightActiveLineGutter,
  drawSelection, hoverTooltip,
} from "@codemirror/view";
import { defaultKeymap, history, historyKeymap } from "@codemirror/commands";
import { syntaxHighlighting, defaultHighlightStyle } from "@codemirror/language";
import { setDiagnostics, lintGutter } from "@codemirror/lint";
import { languageFor } from "./modes.js";

/** Milliseconds after the last keystroke before the post is re-posted. */
const DEBOUNCE_MS = 50;
/** Height of one program line in the virtual list, in pixels. */
const ROW = 18;

const $ = (id) => document.getElementById(id);

async function api(endpoint, body) {
  const response = await fetch(`/api/${endpoint}`, {
    method: "POST",
    headers: { "Content-Type": "application/json" },
    body: JSON.stringify(body ?? {}),
  });
  const value = await response.json().catch(() => ({ error: response.statusText }));
  if (!response.ok) throw new Error(value.error || `${response.status}`);
  return value;
}

// What the page holds.
const doc = { path: null, encoding: "utf-8" };
const result = { program: [], trace: null, findings: [] };
const workbench = {
  debounce: DEBOUNCE_MS,
  updates: 0,
  lastLatency: null,
  lastServerMs: null,
  selectedLine: null,
  view: null,
  /** Selects the first occurrence of `text` in the post (for tests and the find box). */
  find(text) {
    const at = workbench.view.state.doc.toString().indexOf(text);
    if (at < 0) return false;
    workbench.view.dispatch({ selection: { anchor: at, head: at + text.length }, scrollIntoView: true });
    workbench.view.focus();
    return true;
  },
};
window.workbench = workbench;

// The post line the trace points at: a line decoration.
const setTraced = StateEffect.define();
const tracedField = StateField.define({
  create: () => Decoration.none,
  update(deco, tr) {
    deco = deco.map(tr.changes);
    for (const e of tr.effects) {
      if (e.is(setTraced)) {
        deco = e.value === null ? Decoration.none
          : Decoration.set([Decoration.line({ class: "cm-traced" }).range(e.value)]);
      }
    }
    return deco;
  },
  provide: (f) => EditorView.decorations.from(f),
});

// Hover: the registry's explanation, from the language server's analysis.
const hover = hoverTooltip(async (view, pos) => {
  if (!doc.path) return null;
  let h;
  try {
    h = await api("hover", { path: doc.path, text: view.state.doc.toString(), encoding: doc.encoding, offset: pos });
  } catch { return null; }
  if (!h) return null;
  return {
    pos: h.from, end: h.to, above: true,
    create() {
      const dom = document.createElement("div");
      dom.className = "cm-hover-doc";
      dom.textContent = h.markdown.replace(/\*\*/g, "");
      return { dom };
    },
  };
});

const language = new Compartment();
let pending = null;
let editStarted = null;

const view = new EditorView({
  parent: $("editor"),
  state: EditorState.create({
    doc: "",
    extensions: [
      lineNumbers(), highlightActiveLineGutter(), highlightActiveLine(), drawSelection(), history(),
      keymap.of([...defaultKeymap, ...historyKeymap]),
      syntaxHighlighting(defaultHighlightStyle, { fallback: true }),
      language.of([]), lintGutter(), tracedField, hover,
      EditorView.updateListener.of((u) => { if (u.docChanged) edited(); }),
    ],
  }),
});
workbench.view = view;

function edited() {
  if (editStarted === null) editStarted = performance.now();
  $("save-status").textContent = "";
  clearTimeout(pending);
  pending = setTimeout(update, DEBOUNCE_MS);
  $("save").disabled = false;
}

// The toolpath chosen in the picker.
function toolpathChoice() {
  const value = $("toolpath").value;
  if (value.startsWith("file:")) return { kind: "file", path: value.slice(5) };
  if (value.startsWith("pattern:")) return { kind: "pattern", name: value.slice(8), moves: Number($("moves").value) || 1000 };
  return null;
}

// The chosen toolpath file's lines, to show the one an NC line came from.
const toolpathText = { path: null, lines: null };
async function loadToolpathText() {
  const choice = toolpathChoice();
  const path = choice && choice.kind === "file" ? choice.path : null;
  if (path === toolpathText.path) return;
  toolpathText.path = path;
  toolpathText.lines = null;
  if (!path) return;
  try {
    const opened = await api("open", { path });
    if (toolpathText.path === path) toolpathText.lines = opened.text.split("\n");
  } catch { /* too large to show, or unreadable: the trace names the line only */ }
}

let generation = 0;
async function update() {
  if (!doc.path) return;
  const mine = ++generation;
  const started = editStarted ?? performance.now();
  editStarted = null;
  const text = view.state.doc.toString();
  const loading = loadToolpathText();
  let out;
  try {
    out = await api("post", { path: doc.path, text, encoding: doc.encoding, toolpath: toolpathChoice() });
    await loading;
  } catch (e) {
    status(`error: ${e.message}`);
    return;
  }
  if (mine !== generation) return; // a newer edit is on its way
  showDiagnostics(out.diagnostics || []);
  if (out.program !== undefined) {
    result.program = splitLines(out.program);
    result.trace = out.trace;
    result.findings = out.findings || [];
    renderProgram();
    renderFindings(out);
    $("plot").innerHTML = out.svg || `<p class="note">${escapeHtml(out.verify_note || "no backplot")}</p>`;
  } else {
    $("program-info").textContent = out.note || "";
  }
  requestAnimationFrame(() => {
    workbench.lastLatency = performance.now() - started;
    workbench.lastServerMs = out.elapsed_ms ?? null;
    workbench.updates++;
    document.body.dataset.updates = String(workbench.updates);
    status(out.program !== undefined
      ? `posted ${out.events} events into ${out.lines} lines in ${Math.round(out.elapsed_ms)} ms (edit to page ${Math.round(workbench.lastLatency)} ms)`
      : out.note || "");
  });
}

function splitLines(text) {
  const lines = text.split("\n");
  if (lines.length && lines[lines.length - 1] === "") lines.pop();
  return lines;
}

function escapeHtml(s) {
  return String(s).replace(/[&<>"]/g, (c) => ({ "&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;" })[c]);
}

function status(text) { $("status").textContent = text; }

function showDiagnostics(list) {
  const length = view.state.doc.length;
  const clamp = (n) => Math.max(0, Math.min(length, n ?? 0));
  const diagnostics = list.map((d) => {
    const from = clamp(d.from);
    const to = Math.max(from, clamp(d.to));
    const message = [`${d.code ? `${d.code}: ` : ""}${d.message}${d.label ? ` (${d.label})` : ""}`]
      .concat(d.at ? [`in ${d.at}`] : [], d.help ? [`help: ${d.help}`] : [], (d.notes || []).map((n) => `note: ${n}`))
      .join("\n");
    return {
      from, to, severity: d.severity === "note" ? "info" : d.severity, source: d.code || "postc", message,
      actions: (d.fixes || []).map((f) => ({
        name: f.title,
        apply(v) { v.dispatch({ changes: { from: f.from, to: f.to, insert: f.insert } }); },
      })),
    };
  });
  view.dispatch(setDiagnostics(view.state, diagnostics));
  const errors = list.filter((d) => d.severity === "error").length;
  $("diag-count").textContent = `${errors} error(s), ${list.length - errors} other`;
}

// The program pane: a virtual list (only the rows in sight are in the page).
const programBox = $("program");
const spacer = document.createElement("div");
spacer.className = "spacer";
const rows = document.createElement("div");
rows.className = "rows";
programBox.append(spacer, rows);
programBox.addEventListener("scroll", () => renderRows());

function renderProgram() {
  spacer.style.height = `${result.program.length * ROW}px`;
  $("program-info").textContent = `${result.program.length} lines`;
  renderRows();
}

function renderRows() {
  const first = Math.max(0, Math.floor(programBox.scrollTop / ROW) - 5);
  const count = Math.ceil(programBox.clientHeight / ROW) + 10;
  const last = Math.min(result.program.length, first + count);
  const flagged = new Map(result.findings.map((f) => [f.line, f.severity]));
  const parts = [];
  for (let i = first; i < last; i++) {
    const n = i + 1;
    const cls = ["row", n === workbench.selectedLine ? "selected" : "", flagged.has(n) ? `flag-${flagged.get(n)}` : ""].join(" ");
    parts.push(`<div class="${cls}" data-line="${n}" style="top:${i * ROW}px"><span class="ln">${n}</span>${escapeHtml(result.program[i])}</div>`);
  }
  rows.innerHTML = parts.join("");
}

rows.addEventListener("click", (e) => {
  const row = e.target.closest(".row");
  if (row) selectLine(Number(row.dataset.line), false);
});

/** Selects NC line `n`: the post line that wrote it and its toolpath event. */
function selectLine(n, scroll) {
  workbench.selectedLine = n;
  if (scroll) programBox.scrollTop = Math.max(0, (n - 5) * ROW);
  renderRows();
  const t = result.trace;
  const postLine = t && t.post[n - 1];
  const event = t ? t.event[n - 1] : -1;
  const tpLine = t ? t.toolpath[n - 1] : 0;
  if (postLine > 0 && postLine <= view.state.doc.lines) {
    const line = view.state.doc.line(postLine);
    view.dispatch({ effects: [setTraced.of(line.from), EditorView.scrollIntoView(line.from, { y: "center" })] });
  } else {
    view.dispatch({ effects: setTraced.of(null) });
  }
  const shown = tpLine > 0 && toolpathText.lines ? toolpathText.lines[tpLine - 1] : undefined;
  $("trace-toolpath").textContent = shown === undefined ? "" : `toolpath line ${tpLine}: ${shown.slice(0, 200)}`;
  const parts = [`NC line ${n}`];
  parts.push(postLine > 0 ? `written by post line ${postLine}` : "no post line");
  if (event >= 0) parts.push(`for toolpath event ${event}${tpLine > 0 ? ` (toolpath line ${tpLine})` : ""}`);
  else parts.push("before the first or after the last toolpath event");
  $("trace").textContent = parts.join(" · ");
}

function renderFindings(out) {
  const list = $("findings");
  list.innerHTML = "";
  const v = out.verify;
  $("verify").textContent = v
    ? `verify: ${v.errors} error(s), ${v.warnings} warning(s); ${v.matched} of ${v.expected} toolpath moves made`
    : out.verify_note || "";
  for (const f of result.findings) {
    const li = document.createElement("li");
    li.className = `finding ${f.severity}`;
    li.textContent = `#${f.number} ${f.code} line ${f.line}: ${f.message}`;
    li.addEventListener("click", () => selectFinding(f));
    list.append(li);
  }
}

/** A finding: its NC line, the post line behind it, its mark on the backplot. */
function selectFinding(f) {
  selectLine(f.line, true);
  for (const g of document.querySelectorAll("#plot g.finding")) {
    g.classList.toggle("marked", g.textContent.trim() === String(f.number));
  }
}

// Pickers.
async function loadPickers() {
  const [posts, toolpaths] = await Promise.all([api("posts"), api("toolpaths")]);
  const postSel = $("post");
  const add = (sel, group, items) => {
    if (!items.length) return;
    const og = document.createElement("optgroup");
    og.label = group;
    for (const [value, label] of items) og.append(new Option(label, value));
    sel.append(og);
  };
  const short = (p) => p.replace(/^.*\/corpus\//, "corpus/");
  add(postSel, "given", posts.start ? [[posts.start, posts.start]] : []);
  add(postSel, "corpus", posts.corpus.map((p) => [p, short(p)]));
  const tpSel = $("toolpath");
  add(tpSel, "given", toolpaths.start ? [[`file:${toolpaths.start}`, toolpaths.start]] : []);
  add(tpSel, "corpus", toolpaths.corpus.map((p) => [`file:${p}`, short(p)]));
  add(tpSel, "generated", toolpaths.patterns.map((p) => [`pattern:${p.name}`, `${p.name}: ${p.help}`]));
  $("moves").max = String(toolpaths.max_moves);
  if (posts.start || posts.corpus.length) await openPost(posts.start || posts.corpus[0]);
}

async function openPost(path) {
  const opened = await api("open", { path });
  doc.path = path;
  doc.encoding = opened.encoding;
  $("post").value = path;
  view.dispatch({
    changes: { from: 0, to: view.state.doc.length, insert: opened.text },
    effects: [language.reconfigure(languageFor(path)), setTraced.of(null)],
  });
  $("save").disabled = true;
  $("file-info").textContent = `${opened.dialect || "?"} · ${opened.encoding}${opened.crlf ? " · CRLF" : ""}`;
  await update();
}

$("post").addEventListener("change", () => openPost($("post").value).catch((e) => status(`error: ${e.message}`)));
$("toolpath").addEventListener("change", () => {
  $("moves").hidden = !$("toolpath").value.startsWith("pattern:");
  update();
});
$("moves").addEventListener("change", () => update());

// Dropping a toolpath file on the page.
document.addEventListener("dragover", (e) => e.preventDefault());
document.addEventListener("drop", async (e) => {
  e.preventDefault();
  const file = e.dataTransfer?.files?.[0];
  if (!file) return;
  try {
    const kept = await api("drop", { name: file.name, text: await file.text() });
    const option = new Option(`dropped: ${file.name}`, `file:${kept.path}`);
    $("toolpath").append(option);
    $("toolpath").value = option.value;
    await update();
  } catch (err) { status(`error: ${err.message}`); }
});

// Save.
$("save").addEventListener("click", async () => {
  try {
    const saved = await api("save", { path: doc.path, text: view.state.doc.toString() });
    $("save-status").textContent = `saved ${saved.path} (${saved.bytes} bytes)`;
    $("save").disabled = true;
  } catch (e) { $("save-status").textContent = `not saved: ${e.message}`; }
});

// Convert, in the second pane.
const convertedLanguage = new Compartment();
const converted = new EditorView({
  parent: $("converted"),
  state: EditorState.create({
    doc: "",
    extensions: [
      lineNumbers(), EditorState.readOnly.of(true),
      syntaxHighlighting(defaultHighlightStyle, { fallback: true }), convertedLanguage.of([]),
    ],
  }),
});
workbench.converted = converted;
$("convert").addEventListener("click", async () => {
  const to = $("target").value;
  try {
    const out = await api("convert", { path: doc.path, text: view.state.doc.toString(), encoding: doc.encoding, to });
    const text = out.text !== undefined
      ? out.text
      : [out.note].concat((out.diagnostics || []).map((d) => `${d.severity} ${d.code}${d.line ? ` (post line ${d.line})` : ""}: ${d.message}`)).join("\n");
    converted.dispatch({
      changes: { from: 0, to: converted.state.doc.length, insert: text },
      effects: convertedLanguage.reconfigure(out.extension ? languageFor(`x.${out.extension}`) : []),
    });
    $("convert-info").textContent = out.text !== undefined ? `as .${out.extension}` : "refused";
  } catch (e) { status(`error: ${e.message}`); }
});

loadPickers().catch((e) => status(`error: ${e.message}`));
