// Checks that dist/ is what `npm run build` makes from src/: builds into
// a temporary folder and compares index.html and the decompressed app.js
// (gzip's bytes may differ between zlib versions; the script may not).
import { execFileSync } from "node:child_process";
import { mkdtempSync, readFileSync, rmSync } from "node:fs";
import { gunzipSync } from "node:zlib";
import { tmpdir } from "node:os";
import { dirname, join } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const fresh = mkdtempSync(join(tmpdir(), "postc-web-"));
try {
  execFileSync(process.execPath, [join(here, "build.mjs"), fresh], { stdio: "inherit" });
  const same = (name, read) => read(join(here, "dist", name)).equals(read(join(fresh, name)));
  const plain = (p) => readFileSync(p);
  const unzipped = (p) => gunzipSync(readFileSync(p));
  const stale = [["index.html", plain], ["app.js.gz", unzipped]].filter(([n, r]) => !same(n, r)).map(([n]) => n);
  if (stale.length) {
    console.error(`web/dist is not what web/src builds (${stale.join(", ")}): run \`npm run build\` in web/ and commit dist/`);
    process.exit(1);
  }
  console.log("web/dist is up to date");
} finally {
  rmSync(fresh, { recursive: true, force: true });
}
