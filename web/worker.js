// The page's worker: the same wasm module as the page, instantiated on another thread, runs the
// jobs the page sends it (crates/app/src/platform/web.rs) so that the page goes on drawing while
// a big mesh loads. The page's first message is its compiled module ({module}), which this
// worker instantiates without downloading or compiling it again. Replies: {id, kind: "progress"
// | "done", bytes} and, when a job threw (a panic in the module), {id, kind: "failed", message},
// after which this worker closes: the page starts a new one for the next job.
import init, { run_job } from "./inertia_lab_web.js";

let ready;

self.onmessage = async ({ data }) => {
  if (data.module) {
    ready = init({ module_or_path: data.module });
    return;
  }
  const { id, name, input } = data;
  try {
    await (ready ??= init());
    run_job(name, input, (done, bytes) =>
      self.postMessage({ id, kind: done ? "done" : "progress", bytes }, [bytes.buffer]));
  } catch (e) {
    self.postMessage({ id, kind: "failed", message: `${name}: ${e}` });
    self.close();
  }
};
