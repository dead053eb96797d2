// The page's state and the actions every input leads to (UI, drop, links, window.zomeify): load
// a file, run, cancel, open a link, refresh the results. Failures become one status line and
// never replace the model on screen.
import { Event } from './protocol.js';
import { SAMPLES, DEFAULT_SAMPLE, sampleUrl, fetchBytes } from './samples.js';
import { pageUrlWith, copyText, resolutionFromLink, fragmentWithResolution } from './share_link.js';
import { modelBaseName, fileNameFromUrl, isModelFileName } from './file_names.js';
import { missingText, ownedName, resultFitText } from './kits.js';

/**
 * What a builder wants to know of the model beside its parts: how far it is from the shape (after a
 * run; the core's own sentence, in mm) and whether its parts fit side by side (any model).
 */
export function qualityText(summary) {
  const lines = [];
  const fidelity = summary.stats && summary.stats.fidelity;
  if (fidelity && fidelity.summary) lines.push(sentence(plainFidelity(fidelity.summary)));
  if (summary.clearance) {
    const c = summary.clearance;
    lines.push(summary.clashes > 0 ? `Cannot be built as it is: ${c}.` : `Buildable: ${c}.`);
  }
  const mirror = summary.stats && summary.stats.mirror;
  if (mirror && mirror.used && mirror.model) {
    lines.push(mirror.model.symmetric
      ? `Mirror-symmetric (about a plane across the ${mirror.axis} axis): every ball and strut has its mirror image.`
      : `Not exactly symmetric: ${mirror.model.balls_without_image} balls have no mirror image.`);
  } else if (mirror && mirror.mode === 'auto' && mirror.message) {
    lines.push(mirror.message);
  }
  const folds = summary.stats && summary.stats.fold_overs;
  if (folds > 0) {
    const where = placesText(summary.stats.fold_over_places);
    lines.push(`${folds} ${folds === 1 ? 'face is' : 'faces are'} turned inside out (fold-overs)${where ? ', ' + where : ''}.`);
  }
  return lines.join(' ');
}

/** Where the fold-overs are, as the core says it ("2 at the left, at the top"): the panels to look at. */
export function placesText(places) {
  const counts = new Map();
  for (const p of places || []) if (p && p.where) counts.set(p.where, (counts.get(p.where) || 0) + 1);
  return [...counts].map(([w, n]) => `${n > 1 ? n + ' ' : ''}${w === 'middle' ? 'in the middle' : 'at the ' + w}`).join(', ');
}

const sentence = (text) => text[0].toUpperCase() + text.slice(1) + '.';
/** The core's note as a sentence after the verdict ("at 6 cells …" → "At 6 cells ….", once). */
const asSentence = (text) => sentence(text.replace(/\.$/, ''));

/** The core's fidelity sentence without its figures in b0 (a strut length few builders know). */
export function plainFidelity(text) {
  return text.replace(/ \([^()]*\bb0\)/g, '');
}

/** Behind "technical details": the Zome check in the core's terms and its whole fidelity sentence. */
export function qualityTechText(s) {
  const check = s.valid === true ? `valid Zome surface, genus ${s.genus}`
    : s.valid === false ? `not a valid Zome surface: ${s.validation || 'no reason given'}` : '';
  const fidelity = s.stats?.fidelity?.summary;
  return [check && sentence(check), fidelity && sentence(fidelity)].filter(Boolean).join(' ');
}

function holes(n) {
  return n === 0 ? 'no hole' : n === 1 ? '1 hole' : `${n} holes`;
}

/**
 * After a lost hole: "try 10 cells" when the core's answer for this resolution names one that keeps
 * the holes; otherwise the page adds no advice of its own (0) and points to the core's note under
 * the resolution, which says why (-1 when there is no such note: nothing is added).
 */
function tryText(keeping) {
  return keeping > 0 ? ` (try ${keeping} cells)` : keeping === 0 ? ' (the note under the resolution says why)' : '';
}

/**
 * The line under "Parts", in plain words: the counts, and whether the model is a closed Zome
 * surface with as many holes through it as the shape (`surfaceGenus`; null when the model is not
 * the loaded shape's, e.g. a file or a link); `keeping`: a resolution that keeps them.
 */
export function resultText(s, surfaceGenus = null, keeping = 0) {
  const kinds = Object.entries(s.by_kind || {}).map(([k, n]) => `${k} ${n}`).join(', ');
  const counts = `${s.balls} balls, ${s.struts} struts (${kinds})`;
  if (s.valid === null || s.valid === undefined) return counts;
  if (!s.valid) return `${counts} · Not a closed Zome surface${s.validation ? `: ${s.validation}` : ''}`;
  if (surfaceGenus !== null && s.genus !== surfaceGenus) {
    return `${counts} · Warning: the shape has ${holes(surfaceGenus)} through it, this model has ${holes(s.genus)}` +
      `${tryText(keeping)}.`;
  }
  return `${counts} · a closed surface${surfaceGenus === null ? '' : ' with the shape\'s holes'}`;
}

/** A builder's one-line verdict at the end of a run: "581 balls, largest gap 96 mm, buildable". */
export function verdictText(s, surfaceGenus = null, keeping = 0) {
  const parts = [`${s.balls} balls`];
  const gap = s.stats?.fidelity?.hausdorff_mm;
  if (Number.isFinite(gap)) parts.push(`largest gap ${Math.round(gap)} mm`);
  parts.push(s.clashes > 0 ? 'cannot be built as it is (parts clash)' : 'buildable');
  if (s.valid && surfaceGenus !== null && s.genus !== surfaceGenus) {
    parts.push(`but it has ${holes(s.genus)} through it where the shape has ${holes(surfaceGenus)}${tryText(keeping)}`);
  }
  return parts.join(', ');
}

export class App {
  constructor({ bridge, viewer, controls, plot, parts, status, summaryEl, surfaceEl, qualityEl, surfaceToggleEl,
    qualityTechEl = globalThis.document?.getElementById?.('quality-tech') ?? null,
    mirrorOptionEl = globalThis.document?.getElementById?.('mirror-plane-option') ?? null }) {
    Object.assign(this, { bridge, viewer, controls, plot, parts, status, summaryEl, surfaceEl, qualityEl,
      surfaceToggleEl, qualityTechEl, mirrorOptionEl });
    this.surfaceGenus = null; // of the loaded mesh
    this.modelOfSurface = false; // the model on screen was made from the loaded mesh
    this.queued = null; // a file dropped during a run, loaded when it ends
    this.modelResolution = 0; // the resolution the model on screen was made at (0: not known)
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

  /** An error on the status line; `action` ({label, run}) adds a button that acts on it. */
  fail(message, action = null) {
    this.lastError = message;
    this.status.error(message, action);
  }

  /**
   * Loads mesh or model bytes; returns {ok, kind?, error?}. `run` starts a run after a mesh: true, or
   * a function asked when the file really loads (the "run after loading" box: a file that waited for
   * a run runs only if the box is ticked then). `after`: the message it follows (kept before its own).
   */
  async loadBytes(name, bytes, { run = false, fit = true, chooseResolution = true, fresh = true, after = '',
    thicken = false } = {}) {
    if (this.running) {
      // Not lost: it loads (and runs, if asked) when this run ends, or at once after Cancel.
      this.queued = { name, bytes, options: { run, fit, chooseResolution, fresh, thicken } };
      this.status.note(`${name} will load when this run ends (Cancel to load it now).`);
      return { ok: true, queued: true };
    }
    const note = (text) => this.status.note(after ? `${after} ${text}` : text);
    let result;
    const fitBefore = this.fitNext;
    this.fitNext = fit; // a model's snapshot event arrives before the reply
    // The bytes go to the worker; a copy lets an open sheet be loaded again with a thickness.
    const retry = thicken || isModelFileName(name) ? null : bytes.slice(0);
    try {
      result = await this.bridge.load(name, bytes, { thicken });
    } catch (e) {
      this.fitNext = fitBefore;
      const sheet = retry && /open sheet, not a solid/.test(e.message);
      this.fail(e.message.startsWith(name) ? e.message : `${name}: ${e.message}`, sheet ? {
        label: 'Give it a thickness',
        run: () => this.loadBytes(name, retry, { run, fit, chooseResolution, fresh, thicken: true }),
      } : null);
      return { ok: false, error: this.lastError };
    }
    this.lastError = null;
    this.currentName = modelBaseName(name);
    const runNow = typeof run === 'function' ? run() : run;
    if (result.kind === 'mesh') {
      this.fitNext = fit; // the first model of a new shape is framed
      const r = result.report;
      this.surfaceGenus = r.genus;
      this.viewer.setSurface(await this.bridge.surface());
      if (fresh) this.showNewShape();
      this.surfaceEl.textContent = `${name}: ${r.vertices} vertices, ${r.faces} triangles, ` +
        `${holes(r.genus)} through it` +
        (r.repaired?.length ? ` (repaired: ${r.repaired.join('; ')})` : '');
      note(`${name} loaded.`);
      if (chooseResolution) await this.chooseResolution();
      else this.controls.scheduleEstimate();
      // A run started meanwhile (Run pressed while the mesh loaded) takes the place of this one.
      if (runNow && !this.running) return { ...result, run: await this.run() };
    } else {
      this.modelOfSurface = false;
      // A saved model dropped after its mesh can be worked on (the core checks it was made for it).
      this.modelAfterMesh = this.surfaceGenus !== null;
      // What the file leaves to the builder (a VEF's strut ends without a ball, …), said once.
      const notes = (result.notes || []).map((n) => ` ${n[0].toUpperCase()}${n.slice(1)}.`).join('');
      note(`${name}: model loaded.${notes}`);
      await this.refreshResults();
      this.showModelResolution(this.shownSummary?.stats?.resolution);
    }
    return result;
  }

  /** A new mesh: drawn at once; the old model's results are cleared and the model marked as old. */
  showNewShape() {
    this.viewer.setSurfaceVisible?.(true);
    if (this.surfaceToggleEl) this.surfaceToggleEl.checked = true;
    this.modelOfSurface = false;
    this.modelAfterMesh = false;
    this.controls.shapeChanged?.(); // the last shape's estimate and advice go at once
    this.parts.clear();
    this.showMirrorPlane(null);
    this.plot.reset();
    this.summaryEl.textContent = 'The model on screen was made before this shape was loaded: press Run for this one.';
    this.showQuality(null);
    this.onChange?.();
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
    const putUp = async () => {
      if (model) await this.loadBytes(sample.id + '.zome.json', model, { fit });
      await this.loadBytes(sample.mesh, mesh, { fit: !model, chooseResolution: false, fresh: !model });
      this.modelOfSurface = Boolean(model);
      this.onChange?.(); // the sample's model can be worked on at once
      // The sample's model was made from this mesh: its line now compares their holes.
      if (model && this.shownSummary) this.summaryEl.textContent = resultText(this.shownSummary, this.surfaceGenus);
      this.controls.set({ resolution: sample.resolution });
      if (model) {
        this.modelResolution = sample.resolution;
        this.controls.setResult?.(sample.resolution); // its kit plan is the one under Parts
      }
    };
    // One estimate, for the sample as shown: beside its finished model it names no kits (no quick pass).
    await (this.controls.holdEstimates ? this.controls.holdEstimates(putUp) : putUp());
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
    this.modelOfSurface = false;
    this.status.note('Model from the share link (not recomputed).');
    await this.refreshResults();
    this.showModelResolution(resolutionFromLink(link));
    return { ok: true };
  }

  /**
   * Runs with the form's settings (`options` set into the form first); `extra` goes to the core
   * without touching the form (a step on the model on screen: model_work.js).
   */
  async run(options = {}, extra = {}) {
    if (this.running) throw new Error('a run is in progress');
    this.controls.set(options);
    const opts = { ...this.controls.get(), ...extra };
    this.running = true;
    this.onChange?.();
    this.controls.setRunning(true);
    this.plot.reset();
    this.parts.clear(); // the list follows the new model when the run ends
    this.showMirrorPlane(null); // and its mirror plane, if it has one
    this.summaryEl.textContent = 'Running: the parts list follows when the run ends.';
    this.showQuality(null);
    this.status.note('Running…');
    let final;
    const t0 = performance.now();
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
    const how = final.state === 'cancelled' ? 'Cancelled; kept the best model' : 'Finished';
    const ended = final.state === 'failed' ? '' : `${how} in ${final.seconds.toFixed(1)} s.`;
    // The line says the run ended the moment Run is enabled again; the verdict follows it.
    if (ended) this.status.note(`${ended} Reading the parts…`);
    if (final.state !== 'failed' && final.nodes > 0) {
      this.modelOfSurface = true; // else the old model stays
      this.modelResolution = opts.size_cm > 0 ? 0 : opts.resolution;
    }
    const s = await this.refreshResults();
    // What the run took besides its time, shown under the time for the next run of this shape.
    if (final.state === 'done' && !opts.proposals && opts.seconds > 0) {
      this.controls.setMeasuredSetup?.((performance.now() - t0) / 1000 - opts.seconds);
    }
    if (final.state !== 'failed' && final.nodes > 0) {
      if (s?.stats?.resolution > 0) this.modelResolution = s.stats.resolution; // with a size: what it gave
      this.controls.setResult?.(this.modelResolution);
    }
    const keeping = await this.keepingResolution(s, opts);
    if (keeping !== null) this.summaryEl.textContent = resultText(s, this.surfaceGenus, keeping);
    if (final.state === 'failed') this.fail(`run: ${final.error}`);
    else {
      this.lastError = null;
      const verdict = s ? ` ${verdictText(s, this.modelOfSurface ? this.surfaceGenus : null, keeping ?? -1)}.` : '';
      // A lost hole is said once, by the verdict from the controls' answer; the run's own note then
      // adds nothing (it would be a second voice on the same holes).
      const note = final.note && keeping === null ? asSentence(final.note) : '';
      this.status.note(`${ended}${verdict} ${note}`.trim());
    }
    this.onChange?.(); // Run is enabled again: so are the steps on the model
    this.loadQueued();
    return final;
  }

  /**
   * When the run's model lost the shape's holes, what the result says about it (tryText): the
   * resolution that keeps them from the core's answer for this resolution, the one the controls
   * show, so the estimate, the advice and the result say the same thing; 0 when that answer names
   * none (its note says why), -1 when there is no answer. null when no hole was lost.
   */
  async keepingResolution(s, opts) {
    if (!s?.valid || !this.modelOfSurface || this.surfaceGenus === null || s.genus === this.surfaceGenus) return null;
    let e = this.controls.lastEstimate;
    if (!(e && e.resolution === opts.resolution && !opts.size_cm)) {
      try {
        // Without kits: the controls ask for them again if their line is to name them.
        e = { ...(await this.bridge.estimate(opts.resolution, 0, { kits: false })), resolution: opts.resolution };
        this.controls.showEstimate?.(e, opts.resolution); // the controls show this same answer
      } catch {
        return -1;
      }
    }
    if (e.advice_resolution > 0 && e.advice_resolution !== opts.resolution) return e.advice_resolution;
    return e.kept || !(e.advice || e.message) ? -1 : 0;
  }

  /** The slider shows the resolution the model on screen was made at, when it is known. */
  showModelResolution(resolution) {
    this.modelResolution = resolution > 0 ? resolution : 0;
    this.controls.setResult?.(0); // not a model of the loaded shape
    if (this.modelResolution) this.controls.set({ resolution: this.modelResolution });
  }

  /**
   * The file dropped during the run, now that it has ended: it follows the run's last message
   * rather than replacing it, and runs only if "run after loading" says so now.
   */
  loadQueued() {
    const q = this.queued;
    this.queued = null;
    if (q) this.afterQueued = this.loadBytes(q.name, q.bytes, { ...q.options, after: this.status.el?.textContent ?? '' });
  }

  async cancel() {
    if (!this.running) return;
    this.plot.hold();
    this.status.note('Cancelling…');
    await this.bridge.cancel();
  }

  /**
   * The mirror plane of the model on screen (the parts report's `mirror`, core/parts/mirror_halves.h) drawn
   * in the view, with its view option; null hides both.
   */
  showMirrorPlane(mirror) {
    const plane = mirror ? { axis: 'xyz'.indexOf(mirror.axis), at: mirror.coordinate_b0 } : null;
    this.viewer.setMirrorPlane?.(plane);
    if (this.mirrorOptionEl) this.mirrorOptionEl.hidden = !plane;
  }

  /** The parts list, the result line and the quality line of the model on screen; its summary. */
  async refreshResults() {
    try {
      // With kits chosen, the report says what of this model they lack (after a run: checked on the result).
      const { have } = this.controls.owned?.() ?? { have: '' };
      const report = await this.bridge.parts(have);
      this.parts.show(report);
      this.showMirrorPlane(report.mirror);
      this.showKitResult(report, have);
      const s = await this.bridge.summary();
      this.shownSummary = s;
      this.summaryEl.textContent = resultText(s, this.modelOfSurface ? this.surfaceGenus : null);
      this.showQuality(s);
      this.onChange?.();
      return s;
    } catch (e) {
      this.shownSummary = null;
      this.parts.clear();
      this.showMirrorPlane(null);
      this.showKitResult(null, '');
      this.summaryEl.textContent = '';
      this.showQuality(null);
      this.onChange?.();
      return null;
    }
  }

  /** What the kits owned lack for the model on screen (empty without kits). */
  showKitResult(report, have) {
    const el = globalThis.document?.getElementById?.('kit-missing');
    const missed = Boolean(have && report?.missing && missingText(report.missing));
    if (this.controls) this.controls.kitsMissed = missed;
    if (el) el.textContent = have ? resultFitText(report, ownedName(have)) : '';
  }

  /** The quality line in plain words, its technical terms behind "technical details"; null clears. */
  showQuality(s) {
    if (this.qualityEl) this.qualityEl.textContent = s ? qualityText(s) : '';
    if (this.qualityTechEl) this.qualityTechEl.textContent = s ? qualityTechText(s) : '';
  }

  async shareLink({ copy = true } = {}) {
    const { link } = await this.bridge.link();
    const url = pageUrlWith(fragmentWithResolution(link, this.modelResolution));
    if (copy) {
      const ok = await copyText(url);
      this.status.note(ok ? `Share link copied (${url.length} characters).` : url);
    }
    return url;
  }
}
