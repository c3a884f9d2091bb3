// Runs a CIMCO post over a JSON Lines toolpath with the referee host and
// writes the program to standard output.
//
//   node run.js POST.js TOOLPATH.jsonl            the program
//   node run.js POST.js TOOLPATH.jsonl --bench    timings as JSON, no program
//
// In bench mode the events are read and parsed first (`parse_s`), then the
// post runs over them (`post_s`); `events` counts every event.
"use strict";

var fs = require("fs");
var Host = require("./host.js").Host;

function main(argv) {
    var post = argv[2];
    var toolpath = argv[3];
    var bench = argv.indexOf("--bench") >= 0;
    if (!post || !toolpath) {
        process.stderr.write("usage: node run.js POST.js TOOLPATH.jsonl [--bench]\n");
        return 2;
    }
    var source = fs.readFileSync(post, "utf8");
    var t0 = process.hrtime.bigint();
    var text = fs.readFileSync(toolpath, "utf8");
    var events = [];
    var lines = text.split("\n");
    for (var i = 0; i < lines.length; i++) {
        var line = lines[i].trim();
        if (line !== "") {
            events.push(JSON.parse(line));
        }
    }
    var t1 = process.hrtime.bigint();
    var host = new Host(source, post);
    host.keepOutput = !bench;
    for (var k = 0; k < events.length; k++) {
        host.event(events[k]);
    }
    host.finish();
    var t2 = process.hrtime.bigint();
    if (bench) {
        var parse = Number(t1 - t0) / 1e9;
        var run = Number(t2 - t1) / 1e9;
        process.stdout.write(JSON.stringify({ events: events.length, bytes: host.bytes, parse_s: parse, post_s: run }) + "\n");
    } else {
        process.stdout.write(host.out.join(""));
    }
    return 0;
}

process.exitCode = main(process.argv);
