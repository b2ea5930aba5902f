// The page's worker: the same wasm module as the page, loaded on another thread, runs the jobs
// the page sends it (crates/app/src/platform/web.rs) so that the page goes on drawing while a
// big mesh loads. Replies: {id, kind: "progress" | "done", bytes} and, when a job threw (a panic
// in the module), {id, kind: "failed", message}, after which this worker closes: the page starts
// a new one for the next job.
import init, { run_job } from "./inertia_lab_web.js";

const ready = init();

self.onmessage = async ({ data: { id, name, input } }) => {
  try {
    await ready;
    run_job(name, input, (done, bytes) =>
      self.postMessage({ id, kind: done ? "done" : "progress", bytes }, [bytes.buffer]));
  } catch (e) {
    self.postMessage({ id, kind: "failed", message: `${name}: ${e}` });
    self.close();
  }
};
