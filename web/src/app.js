// The page's state and the actions every input leads to (UI, drop, links, window.zomeify): load
// a file, run, cancel, open a link, refresh the results. Failures become one status line and
// never replace the model on screen.
import { Event } from './protocol.js';
import { SAMPLES, DEFAULT_SAMPLE, sampleUrl, fetchBytes } from './samples.js';
import { pageUrlWith, copyText } from './share_link.js';
import { modelBaseName, fileNameFromUrl } from './file_names.js';

/**
 * What a builder wants to know of the model beside its parts: how far it is from the shape (after a
 * run; the core's own sentence, in mm) and whether its parts fit side by side (any model).
 */
export function qualityText(summary) {
  const lines = [];
  const fidelity = summary.stats && summary.stats.fidelity;
  if (fidelity && fidelity.summary) lines.push(fidelity.summary[0].toUpperCase() + fidelity.summary.slice(1) + '.');
  if (summary.clearance) {
    const c = summary.clearance;
    lines.push(summary.clashes > 0 ? `Cannot be built as it is: ${c}.` : `Buildable: ${c}.`);
  }
  const folds = summary.stats && summary.stats.fold_overs;
  if (folds > 0) lines.push(`${folds} ${folds === 1 ? 'face is' : 'faces are'} turned inside out (fold-overs).`);
  return lines.join(' ');
}

export class App {
  constructor({ bridge, viewer, controls, plot, parts, status, summaryEl, surfaceEl, qualityEl }) {
    Object.assign(this, { bridge, viewer, controls, plot, parts, status, summaryEl, surfaceEl, qualityEl });
    this.running = false;
    this.runCount = 0; // finished runs (scripts and tests wait on it)
    this.currentName = 'model';
    this.fitNext = true;
    this.lastError = null;
    this.lastProgress = null;
    bridge.on(Event.SNAPSHOT, ({ snapshot }) => {
      this.viewer.setModel(snapshot, { fit: this.fitNext });
      this.fitNext = false;
    });
    bridge.on(Event.PROGRESS, ({ progress }) => {
      this.lastProgress = progress;
      this.plot.update(progress);
    });
  }

  fail(message) {
    this.lastError = message;
    this.status.error(message);
  }

  /** Loads mesh or model bytes; returns {ok, kind?, error?}. `run` starts a run after a mesh. */
  async loadBytes(name, bytes, { run = false, fit = true, chooseResolution = true } = {}) {
    if (this.running) {
      this.fail(`${name}: a run is in progress; cancel it first`);
      return { ok: false, error: this.lastError };
    }
    let result;
    const fitBefore = this.fitNext;
    this.fitNext = fit; // a model's snapshot event arrives before the reply
    try {
      result = await this.bridge.load(name, bytes);
    } catch (e) {
      this.fitNext = fitBefore;
      this.fail(e.message.startsWith(name) ? e.message : `${name}: ${e.message}`);
      return { ok: false, error: this.lastError };
    }
    this.lastError = null;
    this.currentName = modelBaseName(name);
    if (result.kind === 'mesh') {
      this.fitNext = fit; // the first model of a new shape is framed
      const r = result.report;
      this.viewer.setSurface(await this.bridge.surface());
      this.surfaceEl.textContent = `${name}: ${r.vertices} vertices, ${r.faces} triangles, genus ${r.genus}` +
        (r.repaired?.length ? ` (repaired: ${r.repaired.join('; ')})` : '');
      this.status.note(`${name} loaded.`);
      if (chooseResolution) await this.chooseResolution();
      else this.controls.scheduleEstimate();
      if (run) return { ...result, run: await this.run() };
    } else {
      this.status.note(`${name}: model loaded.`);
      await this.refreshResults();
    }
    return result;
  }

  async loadFile(file, options) {
    return this.loadBytes(file.name, await file.arrayBuffer(), options);
  }

  async loadUrl(url, options) {
    const name = fileNameFromUrl(url, document.baseURI);
    let bytes;
    try {
      bytes = await fetchBytes(url);
    } catch (e) {
      this.fail(`${name}: could not fetch it (${e.message})`);
      return { ok: false, error: this.lastError };
    }
    return this.loadBytes(name, bytes, options);
  }

  /** Fetches a sample's mesh and finished model (bytes), e.g. before the core is up. */
  static fetchSample(id = DEFAULT_SAMPLE) {
    const sample = SAMPLES.find((s) => s.id === id) || SAMPLES[0];
    return {
      sample,
      mesh: fetchBytes(sampleUrl(sample.mesh)),
      model: fetchBytes(sampleUrl(sample.id + '.zome.json')).catch(() => null),
    };
  }

  /** Shows a bundled sample: its mesh (ready to run again) and its precomputed finished model. */
  async showSample(id = DEFAULT_SAMPLE, fetched = App.fetchSample(id), { fit = true } = {}) {
    const { sample } = fetched;
    const [mesh, model] = await Promise.all([fetched.mesh, fetched.model]);
    if (model) await this.loadBytes(sample.id + '.zome.json', model, { fit });
    await this.loadBytes(sample.mesh, mesh, { fit: !model, chooseResolution: false });
    this.controls.set({ resolution: sample.resolution });
    this.status.note(`Sample: ${sample.label} (${sample.credit}). Drop your own mesh anywhere, or press Run.`);
    if (!model) await this.run();
  }

  /** The core's resolution for the loaded mesh, set on the slider before any run (issue 26). */
  async chooseResolution() {
    try {
      await this.controls.chooseAutomatically(() => this.bridge.autoResolution());
    } catch (e) {
      this.controls.scheduleEstimate(); // the slider keeps its value; the estimate says what it gives
      console.warn(`automatic resolution: ${e.message}`);
    }
  }

  async openLink(link) {
    this.fitNext = true;
    try {
      await this.bridge.openLink(link);
    } catch (e) {
      this.fitNext = false;
      this.fail(`share link: ${e.message}`);
      return { ok: false, error: this.lastError };
    }
    this.lastError = null;
    this.currentName = 'shared-model';
    this.status.note('Model from the share link (not recomputed).');
    await this.refreshResults();
    return { ok: true };
  }

  async run(options = {}) {
    if (this.running) throw new Error('a run is in progress');
    this.controls.set(options);
    const opts = this.controls.get();
    this.running = true;
    this.controls.setRunning(true);
    this.plot.reset();
    this.status.note('Running…');
    let final;
    try {
      final = await this.bridge.run(opts);
    } catch (e) {
      final = { state: 'failed', error: e.message };
    } finally {
      this.running = false;
      this.runCount++;
      this.controls.setRunning(false);
    }
    this.lastProgress = final;
    if (final.state === 'failed') this.fail(`run: ${final.error}`);
    else {
      this.lastError = null;
      const how = final.state === 'cancelled' ? 'Cancelled; kept the best model' : 'Finished';
      this.status.note(`${how} in ${final.seconds.toFixed(1)} s. ${final.note || ''}`.trim());
    }
    await this.refreshResults();
    return final;
  }

  async cancel() {
    if (this.running) await this.bridge.cancel();
  }

  async refreshResults() {
    try {
      this.parts.show(await this.bridge.parts());
      const s = await this.bridge.summary();
      const kinds = Object.entries(s.by_kind).map(([k, n]) => `${k} ${n}`).join(', ');
      const valid = s.valid === null ? '' : s.valid ? ` · valid, genus ${s.genus}` : ' · NOT valid';
      this.summaryEl.textContent = `${s.balls} balls, ${s.struts} struts (${kinds})${valid}`;
      if (this.qualityEl) this.qualityEl.textContent = qualityText(s);
    } catch (e) {
      this.parts.clear();
      this.summaryEl.textContent = '';
      if (this.qualityEl) this.qualityEl.textContent = '';
    }
  }

  async shareLink({ copy = true } = {}) {
    const { link } = await this.bridge.link();
    const url = pageUrlWith(link);
    if (copy) {
      const ok = await copyText(url);
      this.status.note(ok ? `Share link copied (${url.length} characters).` : url);
    }
    return url;
  }
}
