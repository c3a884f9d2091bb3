// Builds the workbench's front end into a folder (`npm run build` writes
// dist/, which is committed and embedded in postc): index.html as it is,
// and src/main.js bundled and minified by esbuild, stored gzip-compressed
// as app.js.gz (postc serves it with Content-Encoding: gzip). The same
// sources give the same app.js; web/check.mjs compares a fresh build
// with dist/ by content.
import { build } from "esbuild";
import { gzipSync } from "node:zlib";
import { mkdirSync, readFileSync, writeFileSync } from "node:fs";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const out = process.argv[2] || "dist";
mkdirSync(out, { recursive: true });
const bundle = await build({
  entryPoints: [join(here, "src/main.js")],
  bundle: true,
  minify: true,
  format: "iife",
  target: "es2020",
  legalComments: "eof",
  write: false,
});
const js = bundle.outputFiles[0].contents;
writeFileSync(join(out, "app.js.gz"), gzipSync(js, { level: 9 }));
writeFileSync(join(out, "index.html"), readFileSync(join(here, "src/index.html")));
console.log(`built ${out}: app.js ${js.length} bytes, ${gzipSync(js, { level: 9 }).length} gzipped`);
