// The core worker: owns the wasm module and its Session, answers the requests of protocol.js.
// Threaded build: a run lives in a pthread, so this thread stays free to receive Cancel and to
// poll progress. Single-threaded build: the run blocks this thread and reports through a callback.
import { Request, Event } from '../protocol.js';

const POLL_MS = 100;      // progress events
const SNAPSHOT_MS = 250;  // model updates during a run (≥ 2 per second)
const CHECKPOINT_MS = 1000; // single-threaded run: the model as a file for the page, in case it cancels
const CHECKPOINT_NAME = 'checkpoint.zome.json';

let core = null;
let session = null;
let threaded = false;
let running = false;
let sentVersion = -1;

function post(message, transfer = []) {
  self.postMessage(message, transfer);
}

function parse(json) {
  const value = JSON.parse(json);
  if (value && value.ok === false) throw new Error(value.error);
  return value;
}

function snapshotMessage() {
  const s = session.snapshot();
  sentVersion = s.version;
  return [s, [s.positions.buffer, s.struts.buffer, s.kinds.buffer, s.triangles.buffer]];
}

function postSnapshot() {
  const [s, transfer] = snapshotMessage();
  post({ type: Event.SNAPSHOT, snapshot: s }, transfer);
}

function maybePostSnapshot() {
  if (session.modelVersion() !== sentVersion) postSnapshot();
}

async function init({ wasmBase, threaded: wantThreads }) {
  threaded = wantThreads;
  const file = threaded ? 'zomeify_web.mjs' : 'zomeify_web_st.mjs';
  const { default: createZomeify } = await import(/* @vite-ignore */ wasmBase + file);
  core = await createZomeify({
    locateFile: (p) => wasmBase + p,
    mainScriptUrlOrBlob: wasmBase + file,
    print: (t) => console.log('[core]', t),
    printErr: (t) => console.warn('[core]', t),
  });
  session = new core.Session();
  // The core's run settings (defaults, bounds, presets): the page's form is built from them.
  const schema = JSON.parse(core.runSettingsSchema());
  return { threaded: core.threadedBuild(), maxThreads: core.maxThreads(), defaults: schema.defaults, schema };
}

function runThreaded(options) {
  parse(session.start(JSON.stringify(options)));
  running = true;
  return new Promise((resolve) => {
    let lastSnapshot = 0;
    const timer = setInterval(() => {
      const progress = JSON.parse(session.progress());
      post({ type: Event.PROGRESS, progress });
      const now = performance.now();
      const finished = ['done', 'cancelled', 'failed'].includes(progress.state);
      if (finished || now - lastSnapshot >= SNAPSHOT_MS) {
        lastSnapshot = now;
        maybePostSnapshot();
      }
      if (finished) {
        clearInterval(timer);
        running = false;
        resolve(progress);
      }
    }, POLL_MS);
  });
}

// The model as a file the page keeps, so that a fresh worker can show it if the page ends this one
// to cancel (bridge.js): this thread cannot receive Cancel while a run blocks it.
let checkpointVersion = -1;
function postCheckpoint() {
  checkpointVersion = session.modelVersion();
  const out = session.exportModel(CHECKPOINT_NAME);
  if (out.ok) post({ type: Event.CHECKPOINT, name: CHECKPOINT_NAME, bytes: out.bytes.buffer }, [out.bytes.buffer]);
}

/**
 * A checkpoint of the run's first model at once (a Cancel before the first second must not bring
 * back the model from before the run), then at most one a second.
 */
function checkpointer(startVersion) {
  let last = -Infinity; // when this run last sent one
  return () => {
    const version = session.modelVersion();
    if (version === startVersion || version === checkpointVersion) return; // nothing new
    if (performance.now() - last < CHECKPOINT_MS) return;
    last = performance.now();
    postCheckpoint();
  };
}

function runBlocking(options) {
  running = true;
  let progress = null;
  const startVersion = session.modelVersion();
  checkpointVersion = startVersion; // the page has this model already
  const checkpoint = checkpointer(startVersion);
  try {
    parse(session.runBlocking(JSON.stringify(options), (json) => {
      progress = JSON.parse(json);
      post({ type: Event.PROGRESS, progress });
      maybePostSnapshot();
      checkpoint();
      return false; // this thread cannot receive Cancel while it runs
    }, SNAPSHOT_MS / 1000));
  } finally {
    running = false;
  }
  maybePostSnapshot();
  // The finished model too: a later run cancelled before its first model brings this one back.
  if (session.modelVersion() !== checkpointVersion) postCheckpoint();
  return JSON.parse(session.progress());
}

// Chromium compiles wasm functions lazily, on their first call, and optimises them again once hot,
// on background threads. Left to the user's first run, that burst of compiling (seconds of CPU)
// competes with the annealing threads and with the page's frames on a 2-core machine. A short run
// on a generated octahedron, in its own Session, right after start-up moves it out of the way.
const OCTAHEDRON_OBJ = 'v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1\n' +
  'f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n';
const WARM_UP_RUN = { resolution: 7, proposals: 40000, seconds: 0, threads: 1, seed: 1 };

function warmUp() {
  const t0 = performance.now();
  const scratch = new core.Session();
  try {
    parse(scratch.loadMesh(new TextEncoder().encode(OCTAHEDRON_OBJ), 'warm-up.obj', false));
    parse(scratch.runBlocking(JSON.stringify(WARM_UP_RUN), () => false, 1));
    parse(scratch.parts(''));
  } finally {
    scratch.delete();
  }
  return { ms: performance.now() - t0 };
}

const handlers = {
  [Request.INIT]: init,
  [Request.LOAD]: ({ name, bytes, thicken = false }) => {
    const result = parse(session.loadMesh(new Uint8Array(bytes), name, thicken));
    if (result.kind === 'model') postSnapshot();
    return result;
  },
  [Request.OPEN_LINK]: ({ link }) => {
    const result = parse(session.openLink(link));
    postSnapshot();
    return result;
  },
  [Request.ESTIMATE]: ({ resolution, target = 0, kits = true }) =>
    parse(session.estimate(resolution, Number(target), kits !== false)),
  [Request.ESTIMATE_SIZE]: ({ sizeCm, target = 0 }) => parse(session.estimateSize(Number(sizeCm), Number(target))),
  [Request.KIT_CHECK]: ({ have, balls }) => parse(session.kitCheck(String(have ?? ''), Number(balls) || 0)),
  [Request.FIT_KITS]: ({ have, maxResolution, shrink }) =>
    parse(session.fitKits(String(have ?? ''), Math.trunc(Number(maxResolution) || 0), Boolean(shrink))),
  [Request.AUTO_RESOLUTION]: () => parse(session.autoResolution()),
  [Request.RUN]: ({ options }) => {
    if (running) throw new Error('a run is in progress');
    return threaded ? runThreaded(options) : runBlocking(options);
  },
  [Request.CANCEL]: () => {
    session.cancel();
    return {};
  },
  [Request.SNAPSHOT]: () => snapshotMessage(),
  [Request.SURFACE]: () => {
    const s = session.surface();
    return s ? [s, [s.positions.buffer, s.triangles.buffer]] : null;
  },
  [Request.PARTS]: ({ have }) => parse(session.parts(String(have ?? ''))),
  [Request.BUILD_PLAN]: ({ up }) => parse(session.buildPlan(up || 'y')),
  [Request.EXPORT]: ({ name, options }) => {
    const out = options
      ? session.exportModelWith(name, options.vefFaces !== false, options.objUnits ?? 'mm')
      : session.exportModel(name);
    if (!out.ok) throw new Error(out.error);
    return [{ name, bytes: out.bytes }, [out.bytes.buffer]];
  },
  [Request.LINK]: () => parse(session.link()),
  [Request.SUMMARY]: () => parse(session.summary()),
  [Request.WARM_UP]: () => {
    if (running) throw new Error('a run is in progress');
    return warmUp();
  },
};

// Handlers that return [result, transferList] hand their buffers over instead of copying.
const transfers = new Set([Request.SNAPSHOT, Request.SURFACE, Request.EXPORT]);

self.onmessage = async ({ data }) => {
  const { id, type } = data;
  try {
    if (!handlers[type]) throw new Error(`unknown request '${type}'`);
    if (type !== Request.INIT && !session) throw new Error('the core is not ready yet');
    const value = await handlers[type](data);
    if (transfers.has(type) && Array.isArray(value)) post({ id, type: 'reply', ok: true, result: value[0] }, value[1]);
    else post({ id, type: 'reply', ok: true, result: value });
  } catch (e) {
    const message = e instanceof Error ? e.message : typeof e === 'number' ? `internal error (${e})` : String(e);
    post({ id, type: 'reply', ok: false, error: message });
    if (type === Request.INIT) post({ type: Event.FATAL, error: message });
  }
};
