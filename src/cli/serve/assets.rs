//! The workbench's front end, embedded in the binary: `web/dist/`, built
//! from `web/` by `npm run build` and committed, so that building postc
//! needs no Node.js. The script is stored gzip-compressed (smaller binary)
//! and served as it is, with `Content-Encoding: gzip`.

use super::Reply;

const INDEX: &[u8] = include_bytes!("../../../web/dist/index.html");
const APP_JS_GZ: &[u8] = include_bytes!("../../../web/dist/app.js.gz");

/// The file at a URL path of the front end.
pub fn get(url: &str) -> Reply {
    match url {
        "/" | "/index.html" => {
            Reply { status: 200, content_type: "text/html; charset=utf-8", body: INDEX.to_vec(), gzip: false }
        }
        "/app.js" => {
            Reply { status: 200, content_type: "text/javascript; charset=utf-8", body: APP_JS_GZ.to_vec(), gzip: true }
        }
        _ => Reply::error(404, format!("`{url}` is not part of the workbench")),
    }
}
