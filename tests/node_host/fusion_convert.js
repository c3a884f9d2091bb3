// The Node.js Fusion referee (tests/node_host/fusion.js) with the job's
// product handed as postc's runtime hands it: Fusion's global parameter
// `generated-by` (`__fusion_job(product)` of
// frontends/cimco/src/fusion/host.js, before `onOpen`), the job's `product`,
// else "postc", as a Vectric post's `[PRODUCT]` prints it (docs/vectric.md,
// decision 44). Everything else is fusion.js, run as it is: same
// arguments, same output.
//
//   node fusion_convert.js POST.cps TOOLPATH.jsonl [--property NAME=VALUE]...
//
// When fusion.js makes that call itself, this file has nothing left to add
// (the second call sets the same text).
"use strict";

var fs = require("fs");
var path = require("path");
var vm = require("vm");

var HOST = path.join(__dirname, "..", "..", "frontends", "cimco", "src", "fusion", "host.js");

// The toolpath's job: its first event.
function jobOf(file) {
    var lines = fs.readFileSync(file, "utf8").split("\n");
    for (var i = 0; i < lines.length; i++) {
        var line = lines[i].trim();
        if (line !== "") {
            var e = JSON.parse(line);
            return typeof e === "object" && e.Job ? e.Job : {};
        }
    }
    return {};
}

var job = process.argv[3] ? jobOf(process.argv[3]) : {};
var product = typeof job.product === "string" ? job.product : "postc";

// Once the host API is in the referee's context, hand it the product.
var run = vm.runInContext;
vm.runInContext = function (code, context, options) {
    var result = run.apply(vm, arguments);
    if (options && options.filename === HOST && typeof context.__fusion_job === "function") {
        context.__fusion_job(product);
    }
    return result;
};

require("./fusion.js");
