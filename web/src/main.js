// Entry point: builds the page's parts and wires them together.
import { CoreBridge } from './bridge.js';
import { Event } from './protocol.js';
import { Viewer } from './viewer.js';
import { Controls } from './controls.js';
import { RunPlot } from './plot.js';
import { PartsTable } from './parts_table.js';
import { Downloads } from './downloads.js';
import { Status } from './status.js';
import { App } from './app.js';
import { BuildView } from './build_view.js';
import { ModelWork } from './model_work.js';
import { installApi } from './api.js';
import { setupFileInput } from './file_input.js';
import { SAMPLES } from './samples.js';
import { linkFromLocation } from './share_link.js';
import { snapshotFromZomeJson } from './model_json.js';

const $ = (id) => document.getElementById(id);
const status = new Status($('status'));
const bridge = new CoreBridge();
const viewer = new Viewer($('viewer'));
const controls = new Controls(document, { estimate: (r, target, opts) => bridge.estimate(r, target, opts),
  estimateSize: (cm, target) => bridge.estimateSize(cm, target), kitCheck: (have, balls) => bridge.kitCheck(have, balls),
  fitKits: (have, maxResolution, shrink) => bridge.fitKits(have, maxResolution, shrink) });
const plot = new RunPlot(document);
let app = null;
const parts = new PartsTable(document, { onHover: (kinds) => viewer.highlightKinds(kinds) });
app = new App({ bridge, viewer, controls, plot, parts, status, summaryEl: $('summary'), surfaceEl: $('surface-info'),
  qualityEl: $('quality'), surfaceToggleEl: $('show-surface') });
const buildView = new BuildView(document, { bridge, viewer, status,
  canOpen: () => (app.running ? 'The build plan is made when the run has ended.' : null) });
new Downloads(document, { bridge, status, baseName: () => app.currentName });
const work = new ModelWork(document, { app, bridge });
app.onChange = () => work.refresh();
viewer.onPick = (point) => work.setSpot(point); // a click on the shape chooses the spot of Fix here

let resolveReady, rejectReady;
const ready = new Promise((resolve, reject) => { resolveReady = resolve; rejectReady = reject; });
ready.catch(() => {});
const info = { crossOriginIsolated: self.crossOriginIsolated === true, threaded: false, maxThreads: 1 };
installApi(app, { buildView, work, ready, warmedUp: () => booted.then(() => info.warmUpMs, () => null), info });

bridge.on(Event.FATAL, ({ error }) => {
  status.error(`The core could not start: ${error}`);
  rejectReady(new Error(error));
});

$('run').addEventListener('click', () => {
  const blocked = controls.runBlocker(); // a resolution known to lose the genus needs the user's word
  if (blocked) status.error(blocked);
  else app.run().catch((e) => status.error(e.message));
});
$('cancel').addEventListener('click', () => app.cancel());
$('share').addEventListener('click', () => app.shareLink().catch((e) => status.error(e.message)));
$('show-faces').addEventListener('change', (e) => viewer.setFacesVisible(e.target.checked));
$('show-surface').addEventListener('change', (e) => viewer.setSurfaceVisible(e.target.checked));
$('show-mirror-plane').addEventListener('change', (e) => viewer.setMirrorVisible(e.target.checked));
$('fit').addEventListener('click', () => viewer.fit());
// Narrow screens: the panels under the viewer, one tap away.
for (const b of document.querySelectorAll('[data-jump]')) {
  b.addEventListener('click', () => $(b.dataset.jump).scrollIntoView({ behavior: 'smooth', block: 'start' }));
}
setupFileInput({
  dropTarget: document.body, picker: $('file'), overlay: $('drop-overlay'),
  // Asked when the file loads: a file that waited for a run runs only if the box is ticked then.
  onFile: (file) => app.loadFile(file, { run: () => $('autorun').checked }),
});
for (const s of SAMPLES) {
  const b = document.createElement('button');
  b.textContent = s.label;
  b.title = s.credit;
  b.addEventListener('click', () => app.showSample(s.id).catch((e) => status.error(e.message)));
  $('samples').append(b);
}
window.addEventListener('hashchange', () => {
  const link = linkFromLocation();
  if (link && !app.running) app.openLink(link);
});

async function boot() {
  // The default sample is drawn from its .zome.json while the core is still starting.
  const link = linkFromLocation();
  const early = link ? null : App.fetchSample();
  const shownEarly = early && early.model.then((bytes) => {
    if (!bytes || viewer.snapshot) return false;
    viewer.setModel(snapshotFromZomeJson(new TextDecoder().decode(bytes)), { fit: true });
    info.firstModelMs = performance.now();
    return true;
  }).catch(() => false);

  const started = await bridge.start();
  Object.assign(info, started);
  controls.setMaxThreads(started.maxThreads);
  if (started.schema) controls.setSchema(started.schema);
  if (!info.crossOriginIsolated) {
    $('fallback-note').hidden = false;
  }
  if (link) {
    const opened = await app.openLink(link);
    if (!opened.ok) {
      await app.showSample();
      app.fail(opened.error); // the sample is shown, but the user must see why their link was not
    }
  } else {
    await app.showSample(undefined, early, { fit: !(await shownEarly) });
  }
  info.firstModelMs ??= performance.now();
  info.readyMs = performance.now();
  resolveReady({ ...info });
  // After the first model is up: compile the annealer now rather than in the user's first run.
  const warm = await bridge.warmUp().catch((e) => ({ error: e.message }));
  info.warmUpMs = warm.ms ?? null;
  if (warm.error) console.warn(`warm-up failed: ${warm.error}`);
}

const booted = boot();
booted.catch((e) => {
  status.error(`The page could not start: ${e.message}`);
  rejectReady(e);
});
