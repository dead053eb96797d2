// The page's only door to the core: starts the worker, sends typed requests (protocol.js) and
// returns promises; events (progress, snapshots) go to listeners. Nothing here blocks.
//
// Cancel in the single-threaded build: there a run blocks the worker, which cannot read a Cancel
// until the run ends. So the bridge ends the worker instead and starts a fresh one with the mesh
// and the last model it kept (the files the page loaded, and the checkpoints a run sends every
// second); the run's promise resolves at once as cancelled, and later requests wait for the new
// worker.
import { Request, Event } from './protocol.js';

export class CoreBridge {
  constructor() {
    this.worker = null;
    this.nextId = 1;
    this.pending = new Map();
    this.listeners = { [Event.PROGRESS]: [], [Event.SNAPSHOT]: [], [Event.FATAL]: [] };
    this.info = null;
    this.wasmBase = null;
    this.restarted = null; // a promise while a fresh worker is being set up
    this.kept = { mesh: null, model: null }; // what a fresh worker must load: {name, bytes} or {link}
    this.runRequest = null; // {id, lastProgress, checkpointed} of the run in progress
  }

  /** Starts the worker and loads the threaded build when the page is cross-origin isolated. */
  async start() {
    const threaded = self.crossOriginIsolated === true && typeof SharedArrayBuffer === 'function';
    this.wasmBase = new URL('wasm/', document.baseURI).href;
    this.spawn();
    this.info = await this.send(Request.INIT, { wasmBase: this.wasmBase, threaded });
    return this.info;
  }

  spawn() {
    this.worker = new Worker(new URL('./worker/core_worker.js', import.meta.url), { type: 'module' });
    this.worker.onmessage = ({ data }) => this.receive(data);
    this.worker.onerror = (e) => this.emit(Event.FATAL, { error: e.message || 'the core worker failed to start' });
  }

  /**
   * Ends the blocked worker of a single-threaded run and sets up a fresh one with the mesh and the
   * last model. Returns the cancelled run's final progress at once.
   */
  restart() {
    const run = this.runRequest;
    this.runRequest = null;
    this.worker.terminate();
    const abandoned = [...this.pending.entries()];
    this.pending.clear();
    const final = this.cancelledProgress(run);
    for (const [id, entry] of abandoned) {
      if (id === run?.id) entry.resolve(final);
      else entry.reject(new Error('cancelled'));
    }
    this.emit(Event.PROGRESS, { progress: final }); // the bar and the line say "cancelled", as in threads
    this.spawn();
    const { mesh, model } = this.kept;
    this.restarted = (async () => {
      await this.send(Request.INIT, { wasmBase: this.wasmBase, threaded: false });
      if (mesh) await this.send(Request.LOAD, { name: mesh.name, bytes: mesh.bytes.slice(0), thicken: mesh.thicken });
      if (model?.link) await this.send(Request.OPEN_LINK, { link: model.link });
      else if (model) await this.send(Request.LOAD, { name: model.name, bytes: model.bytes.slice(0) });
    })().catch((e) => this.emit(Event.FATAL, { error: `could not restart the core after cancel: ${e.message}` }))
      .finally(() => { this.restarted = null; });
    return final;
  }

  /** The final progress of a run ended with its worker: how far it got, and which model is kept. */
  cancelledProgress(run) {
    const last = run?.lastProgress || { seconds: 0, fraction: 0 };
    if (!run?.checkpointed) {
      // Stopped before its first model: the one from before the run stays (nodes 0: none made).
      return { ...last, state: 'cancelled', nodes: 0, struts: 0,
        note: 'The run was stopped before it made a model; the model from before it is kept.' };
    }
    return { ...last, state: 'cancelled',
      note: 'The run was stopped; the model as it was up to a second before is kept.' };
  }

  on(type, callback) {
    if (!this.listeners[type]) throw new Error(`unknown event '${type}'`);
    this.listeners[type].push(callback);
  }

  emit(type, data) {
    // A message of an unknown type is dropped, not thrown inside onmessage (where nobody catches it).
    for (const callback of this.listeners[type] || []) callback(data);
  }

  receive(data) {
    if (data.type === Event.CHECKPOINT) {
      this.kept.model = { name: data.name, bytes: data.bytes };
      if (this.runRequest) this.runRequest.checkpointed = true;
      return;
    }
    if (data.type === Event.PROGRESS && this.runRequest) this.runRequest.lastProgress = data.progress;
    if (data.type !== 'reply') {
      this.emit(data.type, data);
      return;
    }
    if (data.id === this.runRequest?.id) this.runRequest = null;
    const entry = this.pending.get(data.id);
    if (!entry) return;
    this.pending.delete(data.id);
    if (data.ok) entry.resolve(data.result);
    else entry.reject(new Error(data.error));
  }

  /** Posts a request now (the worker queues it behind whatever it is doing). */
  send(type, fields = {}, transfer = []) {
    const id = this.nextId++;
    if (type === Request.RUN) this.runRequest = { id, lastProgress: null, checkpointed: false };
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      this.worker.postMessage({ id, type, ...fields }, transfer);
    });
  }

  /** A request, after the fresh worker of a cancelled single-threaded run is ready. */
  async request(type, fields = {}, transfer = []) {
    if (this.restarted) await this.restarted;
    return this.send(type, fields, transfer);
  }

  /**
   * @param {string} name @param {ArrayBuffer} bytes (transferred; a copy is kept for a restart)
   * @param {{thicken?: boolean}} options thicken: an open sheet is given a thickness, not refused
   */
  async load(name, bytes, { thicken = false } = {}) {
    const copy = this.info?.threaded === false ? bytes.slice(0) : null;
    const result = await this.request(Request.LOAD, { name, bytes, thicken }, [bytes]);
    if (copy) this.kept[result.kind === 'mesh' ? 'mesh' : 'model'] = { name, bytes: copy, thicken };
    return result;
  }

  async openLink(link) {
    const result = await this.request(Request.OPEN_LINK, { link });
    this.kept.model = { link };
    return result;
  }

  /** Z0 at `resolution` cells; `kits: false` skips naming the kits (the core's quick pass, 1–3 s here). */
  estimate(resolution, target = 0, { kits = true } = {}) {
    return this.request(Request.ESTIMATE, { resolution, target, kits });
  }
  /** Z0 for a built longest side of `sizeCm` (the core's real_size formula, as `run --size-cm`). */
  estimateSize(sizeCm, target = 0) { return this.request(Request.ESTIMATE_SIZE, { sizeCm, target }); }
  /** Whether a typical model of `balls` balls fits the kits `have` ("creator3, 2x basic"). */
  kitCheck(have, balls) { return this.request(Request.KIT_CHECK, { have, balls }); }
  /** "Fit my kits": the resolution and target the core plans for `have`. */
  fitKits(have, maxResolution = 0, shrink = false) {
    return this.request(Request.FIT_KITS, { have, maxResolution, shrink });
  }
  autoResolution() { return this.request(Request.AUTO_RESOLUTION); }
  run(options) { return this.request(Request.RUN, { options }); }
  /** Threaded build: asks the run to stop. Single-threaded: ends the worker (restart above). */
  cancel() {
    if (this.info?.threaded === false && this.runRequest) return Promise.resolve(this.restart());
    return this.request(Request.CANCEL);
  }
  warmUp() { return this.request(Request.WARM_UP); }
  snapshot() { return this.request(Request.SNAPSHOT); }
  surface() { return this.request(Request.SURFACE); }
  parts(have = '') { return this.request(Request.PARTS, { have }); }
  buildPlan(up = 'y') { return this.request(Request.BUILD_PLAN, { up }); }
  /** @param {{vefFaces?: boolean, objUnits?: 'mm'|'m'}} [options] the writers' options */
  exportModel(name, options) { return this.request(Request.EXPORT, options ? { name, options } : { name }); }
  link() { return this.request(Request.LINK); }
  summary() { return this.request(Request.SUMMARY); }
}
