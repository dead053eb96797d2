// The page's only door to the core: starts the worker, sends typed requests (protocol.js) and
// returns promises; events (progress, snapshots) go to listeners. Nothing here blocks.
import { Request, Event } from './protocol.js';

export class CoreBridge {
  constructor() {
    this.worker = null;
    this.nextId = 1;
    this.pending = new Map();
    this.listeners = { [Event.PROGRESS]: [], [Event.SNAPSHOT]: [], [Event.FATAL]: [] };
    this.info = null;
  }

  /** Starts the worker and loads the threaded build when the page is cross-origin isolated. */
  async start() {
    const threaded = self.crossOriginIsolated === true && typeof SharedArrayBuffer === 'function';
    this.worker = new Worker(new URL('./worker/core_worker.js', import.meta.url), { type: 'module' });
    this.worker.onmessage = ({ data }) => this.receive(data);
    this.worker.onerror = (e) => this.emit(Event.FATAL, { error: e.message || 'the core worker failed to start' });
    const wasmBase = new URL('wasm/', document.baseURI).href;
    this.info = await this.request(Request.INIT, { wasmBase, threaded });
    return this.info;
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
    if (data.type !== 'reply') {
      this.emit(data.type, data);
      return;
    }
    const entry = this.pending.get(data.id);
    if (!entry) return;
    this.pending.delete(data.id);
    if (data.ok) entry.resolve(data.result);
    else entry.reject(new Error(data.error));
  }

  request(type, fields = {}, transfer = []) {
    const id = this.nextId++;
    return new Promise((resolve, reject) => {
      this.pending.set(id, { resolve, reject });
      this.worker.postMessage({ id, type, ...fields }, transfer);
    });
  }

  /** @param {string} name @param {ArrayBuffer} bytes (transferred) */
  load(name, bytes) { return this.request(Request.LOAD, { name, bytes }, [bytes]); }
  openLink(link) { return this.request(Request.OPEN_LINK, { link }); }
  estimate(resolution) { return this.request(Request.ESTIMATE, { resolution }); }
  autoResolution() { return this.request(Request.AUTO_RESOLUTION); }
  run(options) { return this.request(Request.RUN, { options }); }
  cancel() { return this.request(Request.CANCEL); }
  warmUp() { return this.request(Request.WARM_UP); }
  snapshot() { return this.request(Request.SNAPSHOT); }
  surface() { return this.request(Request.SURFACE); }
  parts() { return this.request(Request.PARTS); }
  exportModel(name) { return this.request(Request.EXPORT, { name }); }
  link() { return this.request(Request.LINK); }
  summary() { return this.request(Request.SUMMARY); }
}
