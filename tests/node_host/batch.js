// Runs many CIMCO posts, one after another, over one JSON Lines toolpath
// in one Node.js process (tests/cimco_differential.rs: starting Node.js
// once per post would cost more than running the posts). Each post runs
// in its own `vm` context, so no global of one post is seen by the next.
//
//   node batch.js LIST TOOLPATH.jsonl
//
// LIST names one post file a line. For each POST it writes POST.out (the
// program) when the post ran to the end, or POST.err (the error) when it
// threw, and nothing else.
"use strict";

var fs = require("fs");
var vm = require("vm");
var Host = require("./host.js").Host;

function main(argv) {
    var list = argv[2];
    var toolpath = argv[3];
    if (!list || !toolpath) {
        process.stderr.write("usage: node batch.js LIST TOOLPATH.jsonl\n");
        return 2;
    }
    var events = [];
    var lines = fs.readFileSync(toolpath, "utf8").split("\n");
    for (var i = 0; i < lines.length; i++) {
        var line = lines[i].trim();
        if (line !== "") {
            events.push(JSON.parse(line));
        }
    }
    var posts = fs.readFileSync(list, "utf8").split("\n").filter(function (p) {
        return p !== "";
    });
    for (var n = 0; n < posts.length; n++) {
        var post = posts[n];
        var out;
        try {
            var host = new Host(fs.readFileSync(post, "utf8"), post, vm.createContext({}));
            for (var k = 0; k < events.length; k++) {
                host.event(events[k]);
            }
            host.finish();
            out = host.out.join("");
        } catch (e) {
            fs.writeFileSync(post + ".err", String(e && e.stack ? e.stack : e));
            continue;
        }
        fs.writeFileSync(post + ".out", out);
    }
    return 0;
}

process.exitCode = main(process.argv);
