//! Fusion posts under two JavaScript engines: every corpus `.cps` post
//! that postc runs over the standard milling job prints the same bytes when
//! Node.js runs it with the same host API (`tests/node_host/fusion.js`,
//! which drives `frontends/cimco/src/fusion/host.js` from the toolpath's
//! events as docs/fusion.md describes). A difference is postc's JavaScript
//! engine disagreeing with V8, or the event order disagreeing with a second
//! reading of the documentation.

use std::path::Path;
use std::process::Command;

use crate::fusion_corpus::{posts, shared};
use crate::support;

#[test]
fn node_and_postc_print_the_same_program_for_every_corpus_fusion_post_that_runs() {
    let dir = shared();
    if !dir.is_dir() {
        support::referee_missing("fusion_node", "../shared/corpus/fusion");
        return;
    }
    if support::cimco::node().is_none() {
        support::referee_missing("fusion_node", "node");
        return;
    }
    let tmp = std::env::temp_dir().join(format!("postc-fusion-node-{}", std::process::id()));
    std::fs::create_dir_all(&tmp).expect("temporary folder");
    let job = crate::fusion_corpus::milling_job(&tmp);
    let jsonl = tmp.join("standard_milling.jsonl");
    support::cimco::export_jsonl(&job, &jsonl).expect("export the job");
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/node_host/fusion.js");
    let posts = posts(&dir);
    let next = std::sync::atomic::AtomicUsize::new(0);
    let workers = std::thread::available_parallelism().map_or(2, |n| n.get()).min(8);
    // Each worker takes the next post; compiling a large post recurses
    // deeply in a debug build, so the workers have big stacks.
    let results: Vec<Result<(), String>> = std::thread::scope(|scope| {
        let handles: Vec<_> = (0..workers)
            .map(|_| {
                let (posts, next, job, jsonl, script, dir) = (&posts, &next, &job, &jsonl, &script, &dir);
                std::thread::Builder::new()
                    .stack_size(256 << 20)
                    .spawn_scoped(scope, move || {
                        let mut done = Vec::new();
                        loop {
                            let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                            let Some(post) = posts.get(i) else { break };
                            let name = post.strip_prefix(dir).unwrap_or(post).display().to_string();
                            let Ok(ours) = support::compile(post)
                                .and_then(|compiled| support::cimco::post_toolpath(&compiled, job))
                            else {
                                continue;
                            };
                            let node =
                                Command::new("node").arg(script).arg(post).arg(jsonl).output().expect("run node");
                            done.push(if !node.status.success() {
                                Err(format!("{name}: Node.js stops: {}", String::from_utf8_lossy(&node.stderr)))
                            } else if node.stdout != ours {
                                Err(format!("{name}:\n{}", support::diff(&node.stdout, &ours)))
                            } else {
                                Ok(())
                            });
                        }
                        done
                    })
                    .expect("a thread")
            })
            .collect();
        handles.into_iter().flat_map(|h| h.join().expect("a worker")).collect()
    });
    let same = results.iter().filter(|r| r.is_ok()).count();
    let differ: Vec<String> = results.into_iter().filter_map(Result::err).collect();
    let _ = std::fs::remove_dir_all(&tmp);
    println!("{same} corpus Fusion posts print the same program under Node.js and postc");
    assert!(differ.is_empty(), "{} posts differ (Node.js first, postc second):\n{}", differ.len(), differ.join("\n"));
}
