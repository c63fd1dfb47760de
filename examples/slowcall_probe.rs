//! `cargo run --release --example slowcall_probe -- case.json [case.json …]` — runs a fuzzer case
//! (`{fn, input, pre?}` as `bench/trapfuzz-cases.mjs` makes it) natively through the same `api`
//! function the wasm export calls, and prints the thread CPU time of its `pre` tune and of the
//! call, the simulated pieces the rules' own searches were charged (`rules::work`), and the
//! first 300 characters of the answer or the error (branch `slowcalls`).

use pidlab::api;
use pidlab::rules::work::spent;
use serde_json::Value;

#[path = "common/cpu.rs"]
mod cpu;
use cpu::cpu_now;

fn main() {
    for path in std::env::args().skip(1) {
        let text = std::fs::read_to_string(&path).expect("read the case");
        let case: Value = serde_json::from_str(&text).expect("a JSON case");
        let f = case["fn"].as_str().unwrap_or("").to_string();
        let mut input = case["input"].clone();
        if let Some(pre) = case.get("pre").filter(|p| p.is_object()) {
            let mut t = pre.clone();
            t["plant"] = input["plant"].clone();
            let c0 = cpu_now();
            let r = api::tune(&t);
            println!("{path}: pre tune {:.3} s: {}", cpu_now() - c0, brief(&r));
            if let Ok(v) = r {
                input["controller"] = v["controller"].clone();
            }
        }
        let (c0, w0) = (cpu_now(), spent());
        let r = match f.as_str() {
            "admissible" => api::admissible(&input),
            "sweep" => api::sweep(&input),
            "sweep_grid" => api::sweep_grid(&input),
            "simulate" => api::simulate(&input),
            "tune" => api::tune(&input),
            "analyze" => api::analyze(&input),
            "freqresp" => api::freqresp(&input),
            "export" => api::export(&input),
            other => panic!("{other}: not probed"),
        };
        let (cpu, work) = (cpu_now() - c0, spent() - w0);
        println!(
            "{path}: {f} {cpu:.3} s, {work} pieces charged: {}",
            brief(&r)
        );
    }
}

fn brief(r: &pidlab::error::Result<Value>) -> String {
    let s = match r {
        Ok(v) => format!("ok {v}"),
        Err(e) => format!("error {e}"),
    };
    if std::env::var_os("PROBE_FULL").is_some() {
        return s;
    }
    s.chars().take(300).collect()
}
