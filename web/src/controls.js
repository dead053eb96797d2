// The run controls: resolution (chosen automatically for each mesh, with a live estimate of balls,
// size and kits, and the advisor's suggestion as a button), time presets, target complexity,
// threads, advanced weights and seed. Reads them as protocol RunOptions.
//
// Defaults, bounds and presets come from the core at start-up (setSchema: core/pipeline/
// run_settings.h), so the page, the Session and the CLI share them; these are only the values the
// form shows before the core is up.
import { KITS, haveText, checkSize, estimateFitText, fitPlanText } from './kits.js';

export const PRESETS = { quick: 5, standard: 30, thorough: 120 };
/**
 * The core's judgement of the shape's mirror plane in a builder's words: "The shape is
 * mirror-symmetric to within 0.5 mm (about a plane across its x axis): …", or the core's reason when
 * it is not.
 */
export function mirrorText(m) {
  if (!m) return '';
  if (!m.symmetric) return String(m.message || '');
  const mm = Number(m.rms_mm);
  const within = mm < 0.05 ? 'exactly' : `to within ${mm.toFixed(1)} mm`;
  return `The shape is mirror-symmetric ${within} (about a plane across its ${m.axis} axis): ` +
    'the model is built symmetric, both halves with the same parts.';
}

const DEFAULTS = { resolution: 12, preset: 'standard', seconds: 30, target_nodes: 0, threads: 0, seed: 1,
  weights: { dist: 30, orient: 100, fair: 5, complex: 1, surface: 100, fold: 1 } };
// Past these a suggested model is flagged before anyone buys the parts.
export const LARGE_MODEL = { balls: 3000, metres: 2 };
// The form's inputs for each bounded option of the core's schema.
const BOUNDED_INPUTS = { resolution: 'resolution', seconds: 'seconds', target_nodes: 'target', seed: 'seed',
  proposals: 'proposals' };

// The controls' arithmetic and text, kept pure (no DOM) so web/tests/ can check it.

/** The preset whose time is `seconds`, else 'custom'. */
export function presetForSeconds(seconds) {
  return Object.keys(PRESETS).find((k) => PRESETS[k] === seconds) || 'custom';
}

/** "auto" threads: all cores but one, at least 1, at most maxThreads. */
export function autoThreadCount(cores, maxThreads) {
  return Math.max(1, Math.min((cores || 2) - 1, maxThreads));
}

/** "1.2 m" or "85 cm": a model's longest side at real size. */
export function sizeText(mm) {
  return mm >= 1000 ? `${(mm / 1000).toFixed(1)} m` : `${Math.round(mm / 10)} cm`;
}

/**
 * The kits a model of this estimate takes, as the core names them before a run (a short annealing
 * pass, core/pipeline/kit_estimate.h): `kit_plan`, which the run keeps within, and `kit_plan_low`,
 * the short pass's own mix, the range's other end; docs/page.md has the table.
 */
export function kitsText(e) {
  if (!e.kit_plan) return '';
  const within = `${e.kit_plan} (the run keeps within them)`;
  return !e.kit_plan_low || e.kit_plan_low === e.kit_plan ? within : `about ${e.kit_plan_low} to ${within}`;
}

/** What a model of this estimate costs: balls, struts, size and kits (2.2–2.9 struts per ball). */
export function billText(e, balls = e.nodes) {
  const kits = e.kit_plan ? `, kits: ${kitsText(e)}` : '';
  const size = Number.isFinite(e.size_mm) ? `, ${sizeText(e.size_mm)} across` : '';
  return `≈ ${balls} balls, ${Math.round(2.2 * balls)}–${Math.round(2.9 * balls)} struts${size}${kits}`;
}

/** The estimate line for the chosen resolution (balls from the target when one is set). */
export function estimateText(e, target) {
  return `The model: ${billText(e, target)}`;
}

// What a run takes besides the time chosen (issue 38: "quick (5 s)" took 9.7 s): building the
// starting model before annealing and measuring the result after it. Before a run on a shape the
// page knows only how long its starting model took to build for the estimate; measured on the
// shared meshes (docs/page.md) the rest stays within SETUP.perZ0 × that + SETUP.fixed seconds.
export const SETUP = { perZ0: 2, fixed: 1.5 };

/** Seconds a run adds to its time: measured on this shape's last run, else from the estimate. */
export function setupSeconds(e, measured = 0) {
  if (measured > 0) return measured;
  const z0 = e?.z0_seconds;
  return Number.isFinite(z0) ? SETUP.perZ0 * z0 + SETUP.fixed : 0;
}

/** The line under the time: what the preset's time does not count. */
export function setupText(seconds, measured = false) {
  if (!(seconds > 0)) return '';
  const s = seconds < 10 ? Math.ceil(seconds * 2) / 2 : Math.ceil(seconds);
  return `Plus about ${s} s to build the starting model and measure the result${measured ? ' (the last run)' : ''}.`;
}

/** True when a model of this estimate deserves a warning before it is built. */
export function isLarge(e) {
  return e.nodes > LARGE_MODEL.balls || e.size_mm > LARGE_MODEL.metres * 1000;
}

/** The advisor's warning ('' when Z0 keeps the surface's genus). */
export function adviceText(e, resolution) {
  return e.kept ? '' : (e.advice || `at ${resolution} cells the model's genus is ${e.genus}, ` +
    `the surface's ${e.surface_genus}`);
}

export class Controls {
  /**
   * @param {HTMLElement} root
   * @param {{estimate: (r:number)=>Promise<object>, estimateSize?: (cm:number)=>Promise<object>,
   *   kitCheck?: (have:string, balls:number)=>Promise<object>,
   *   fitKits?: (have:string, maxResolution:number, shrink:boolean)=>Promise<object>}} deps
   */
  constructor(root, { estimate, estimateSize = null, kitCheck = null, fitKits = null }) {
    this.root = root;
    this.estimateFn = estimate;
    this.estimateSizeFn = estimateSize;
    this.kitCheckFn = kitCheck;
    this.fitKitsFn = fitKits;
    this.kitsMissed = false; // the model on screen is a run that missed the kits (App sets it)
    this.el = (id) => root.querySelector('#' + id);
    this.maxThreads = 1;
    this.estimateTimer = null;
    this.estimateSerial = 0;
    this.initialOnly = false; // API only: stop after Z0
    this.lastEstimate = null; // of the resolution shown, for the run's genus check
    this.genusConsent = false; // the user ticked "run anyway" (never ticked for them)
    this.noKeepingGrid = false; // the core's automatic choice found no grid that keeps the holes
    this.autoMessage = '';
    this.resultResolution = 0; // the model on screen is the loaded shape's, made at this resolution
    this.measuredSetup = 0; // seconds the last run on this shape took besides its time (App sets it)
    this.autoTarget = 0; // the automatic choice's ball target, while the form holds it
    this.pinned = false; // a script fixed the resolution: meshes loaded next keep it

    this.el('resolution').addEventListener('input', () => this.set({ resolution: this.el('resolution').value }));
    this.el('preset').addEventListener('change', () => this.presetChanged());
    // Once the person sets the switch, a new estimate no longer sets it for them.
    this.el('mirror')?.addEventListener('change', () => { this.mirrorTouched = true; });
    this.el('size-mode')?.addEventListener('change', () => this.set({ size_cm: this.el('size-mode').checked
      ? Number(this.el('size-cm').value) || 50 : 0 }));
    this.el('size-cm')?.addEventListener('input', () => this.scheduleEstimate());
    this.el('target')?.addEventListener('input', () => this.scheduleEstimate()); // the kits follow the ball target
    for (const { id } of KITS) this.el('kit-' + id)?.addEventListener('input', () => this.scheduleEstimate());
    this.el('fit-kits')?.addEventListener('click', () => this.fitMyKits());
    this.set(DEFAULTS);
  }

  /**
   * The core's run settings (core/pipeline/run_settings.h): defaults, bounds and time presets become
   * the form's starting values and limits. The resolution default (0, automatic) is not a position
   * of the slider: each mesh gets its own on loading (chooseAutomatically).
   */
  setSchema(schema) {
    if (!schema || !schema.defaults) return;
    const d = schema.defaults;
    for (const k of Object.keys(PRESETS)) if (Number.isFinite(schema.presets?.[k])) PRESETS[k] = schema.presets[k];
    for (const k of ['seconds', 'target_nodes', 'threads', 'seed']) if (Number.isFinite(d[k])) DEFAULTS[k] = d[k];
    DEFAULTS.preset = presetForSeconds(DEFAULTS.seconds);
    for (const k of Object.keys(DEFAULTS.weights)) {
      if (Number.isFinite(d.weights?.[k])) DEFAULTS.weights[k] = d.weights[k];
    }
    for (const [key, id] of Object.entries(BOUNDED_INPUTS)) {
      const b = schema.bounds?.[key];
      if (!b) continue;
      this.el(id).min = String(b.min);
      this.el(id).max = String(b.max);
    }
    for (const [k, v] of Object.entries(schema.bounds || {})) {
      if (k.startsWith('weights.')) Object.assign(this.el('w-' + k.slice(8)), { min: String(v.min), max: String(v.max) });
    }
    this.schema = schema;
    const { resolution, ...rest } = DEFAULTS;
    this.set(rest);
  }

  /**
   * The grid and ball target the core picks for the loaded mesh (core/voxel/auto_resolution.h: the
   * default size, or the grid nearest it that keeps the shape's holes), the same as `zomeify run`;
   * shown with its bill before anything runs. The user can still move either.
   */
  async chooseAutomatically(autoResolution) {
    // A size the user asked for (or a script's resolution) stays: the estimate follows the new mesh.
    if (this.pinned || this.sizeMode()) {
      this.scheduleEstimate();
      return null;
    }
    const serial = this.estimateSerial;
    const typed = this.el('target').value !== '' && Number(this.el('target').value) !== this.autoTarget;
    const a = await autoResolution();
    if (serial !== this.estimateSerial) return null; // another shape (or resolution) came meanwhile
    const target = typed ? Number(this.el('target').value) : a.target_nodes || 0; // a typed target stays
    this.set({ resolution: a.resolution, target_nodes: target });
    this.autoTarget = typed ? 0 : target; // goes with this grid: moving the slider clears it
    // No grid keeps the holes: the core's sentence says so and a run goes on (issue 26) without a
    // "run anyway" box, as there is nothing else to choose.
    this.noKeepingGrid = !a.kept;
    this.autoMessage = `Resolution chosen for this shape: ${String(a.message ?? '').replace(/\.$/, '')}.`;
    this.showMirror(a.mirror);
    clearTimeout(this.estimateTimer); // this answer is the estimate of this resolution
    this.estimateSerial++;
    this.showEstimate(a, a.resolution);
    return a;
  }

  /**
   * The shape's mirror plane as the core judged it at the chosen size (core/pipeline/mirror_choice.h):
   * the switch is on when the shape is symmetric (the run then builds both halves alike), with the
   * core's reason when it is not. A switch the person set stays as they set it.
   */
  showMirror(m) {
    const row = this.el('mirror-row');
    if (!row) return;
    row.hidden = !m;
    if (!m) return;
    if (!this.mirrorTouched) this.el('mirror').checked = Boolean(m.symmetric);
    this.el('mirror-note').textContent = mirrorText(m);
  }

  /** A new shape was loaded: the last shape's estimate, advice and consent go at once. */
  shapeChanged() {
    this.mirrorTouched = false;
    this.showMirror(null);
    clearTimeout(this.estimateTimer);
    this.estimateSerial++;
    this.autoMessage = '';
    this.genusConsent = false;
    this.noKeepingGrid = false;
    this.resultResolution = 0;
    this.measuredSetup = 0;
    this.showEstimate(null, 0);
    this.el('estimate').textContent = 'Choosing a resolution for this shape…';
  }

  /** True while the controls show the resolution the model on screen was made at. */
  showsResult(resolution) {
    return this.resultResolution > 0 && this.resultResolution === resolution;
  }

  /**
   * The model on screen is the loaded shape's, made at `resolution` (0: it is not): while the
   * controls show that resolution, its kit plan under Parts is the one kit sentence, so the
   * estimate line names no kits of its own.
   */
  setResult(resolution) {
    this.resultResolution = resolution > 0 ? resolution : 0;
    if (this.lastEstimate) this.showEstimate(this.lastEstimate, this.lastEstimate.resolution);
  }

  /**
   * '' when a run may start; else why not: the estimate knows this resolution loses the genus,
   * another keeps it, and the user has not agreed.
   */
  runBlocker() {
    const e = this.lastEstimate;
    if (this.sizeMode()) return checkSize(this.el('size-cm').value).error;
    if (!e || e.kept || this.genusConsent || this.noKeepingGrid || Number(this.el('resolution').value) !== e.resolution) {
      return '';
    }
    return `${adviceText(e, e.resolution)}. Use the suggested resolution, or tick "run anyway".`;
  }

  setMaxThreads(n) {
    this.maxThreads = n;
    const select = this.el('threads');
    select.replaceChildren(new Option(`auto (${this.autoThreads()})`, '0'));
    for (let t = 1; t <= n; t++) select.add(new Option(String(t), String(t)));
  }

  /** All cores but one: the page, the compositor and (without a GPU) the rasteriser need one. */
  autoThreads() {
    return autoThreadCount(navigator.hardwareConcurrency, this.maxThreads);
  }

  presetChanged() {
    const preset = this.el('preset').value;
    const custom = preset === 'custom';
    this.el('seconds').disabled = !custom;
    if (!custom) this.el('seconds').value = PRESETS[preset];
  }

  /** Applies any subset of RunOptions (plus `preset`). */
  set(o) {
    if (o.resolution !== undefined) {
      // A new resolution: the automatic choice's note, its ball target and any consent to lose the genus go.
      this.autoMessage = '';
      if (this.autoTarget && o.target_nodes === undefined && Number(this.el('target').value) === this.autoTarget) {
        this.el('target').value = '';
      }
      this.autoTarget = 0;
      this.pinned = false; // a script fixed the resolution: meshes loaded next keep it
      this.genusConsent = false;
      this.noKeepingGrid = false;
      this.el('resolution').value = o.resolution;
      this.el('resolution-value').textContent = String(o.resolution);
      this.scheduleEstimate();
    }
    if (o.size_cm !== undefined && this.el('size-mode')) {
      // A size replaces the resolution until it is set to 0 (or a resolution is chosen).
      const on = Number(o.size_cm) > 0;
      this.el('size-mode').checked = on;
      this.el('size-cm').disabled = !on;
      if (on) {
        this.el('size-cm').value = o.size_cm;
        this.autoMessage = ''; // the resolution chosen for the shape no longer applies, nor its ball target
        if (this.autoTarget && Number(this.el('target').value) === this.autoTarget) this.el('target').value = '';
        this.autoTarget = 0;
      }
      this.el('resolution').disabled = on;
      this.scheduleEstimate();
    } else if (o.resolution !== undefined && this.el('size-mode')?.checked) {
      this.el('size-mode').checked = false;
      this.el('size-cm').disabled = true;
      this.el('resolution').disabled = false;
    }
    if (o.preset !== undefined) {
      this.el('preset').value = o.preset;
      this.presetChanged();
    }
    if (o.seconds !== undefined && o.preset === undefined) {
      const preset = presetForSeconds(o.seconds);
      this.el('preset').value = preset;
      this.presetChanged();
      this.el('seconds').value = o.seconds;
    }
    if (o.target_nodes !== undefined) this.el('target').value = o.target_nodes || '';
    if (o.threads !== undefined) this.el('threads').value = String(o.threads);
    if (o.seed !== undefined) this.el('seed').value = o.seed;
    if (o.proposals !== undefined) this.el('proposals').value = o.proposals || '';
    if (o.initial_only !== undefined) this.initialOnly = Boolean(o.initial_only);
    if (o.pinned !== undefined) this.pinned = Boolean(o.pinned);
    if (o.mirror !== undefined && this.el('mirror')) {
      this.el('mirror').checked = o.mirror === 'auto';
      this.mirrorTouched = true;
    }
    for (const [k, v] of Object.entries(o.weights || {})) this.el('w-' + k).value = v;
  }

  /** @returns {import('./protocol.js').RunOptions} */
  get() {
    const num = (id, fallback) => {
      const v = Number(this.el(id).value);
      return Number.isFinite(v) && this.el(id).value !== '' ? v : fallback;
    };
    const threads = Number(this.el('threads').value) || this.autoThreads();
    return {
      resolution: num('resolution', DEFAULTS.resolution),
      seconds: num('seconds', DEFAULTS.seconds),
      target_nodes: num('target', 0),
      threads: Math.min(threads, this.maxThreads),
      seed: num('seed', 1),
      proposals: num('proposals', 0),
      initial_only: this.initialOnly,
      size_cm: this.sizeMode() ? checkSize(this.el('size-cm').value).cm : 0,
      mirror: this.el('mirror')?.checked ? 'auto' : 'off',
      weights: Object.fromEntries(Object.keys(DEFAULTS.weights).map((k) => [k, num('w-' + k, DEFAULTS.weights[k])])),
    };
  }

  /** True when the built size, not the resolution, sets the scale. */
  sizeMode() {
    return Boolean(this.el('size-mode')?.checked);
  }

  /** The kits picker as `--have` text ('' when none), or its error. */
  owned() {
    const counts = Object.fromEntries(KITS.map(({ id }) => [id, this.el('kit-' + id)?.value ?? '']));
    return haveText(counts);
  }

  /** Sets the picker: {creator3: 1, basic: 2}; kits not named go to 0. */
  setKits(counts) {
    for (const { id } of KITS) if (this.el('kit-' + id)) this.el('kit-' + id).value = String(counts[id] ?? 0);
    this.scheduleEstimate();
  }

  /** Before the run: does the estimated model fit the kits owned? (the core's kit check) */
  async showKitFit(e) {
    const out = this.el('kit-fit');
    if (!out) return;
    const { have, error } = this.owned();
    if (error) {
      out.textContent = error;
      return;
    }
    if (!have || !e || !this.kitCheckFn) {
      out.textContent = '';
      return;
    }
    const balls = Number(this.el('target').value) || e.nodes;
    // The plan "Fit my kits" set stays in view while the form still holds it.
    const fit = this.lastFit;
    const planned = fit?.possible && !this.sizeMode() && Number(this.el('resolution').value) === fit.resolution &&
      Number(this.el('target').value) === fit.target_nodes;
    if (planned) {
      out.textContent = this.fitText; // it already says the result is checked: once is enough
      return;
    }
    try {
      out.textContent = estimateFitText(await this.kitCheckFn(have, balls), balls);
    } catch (err) {
      out.textContent = err.message;
    }
  }

  /**
   * "Fit my kits": the core plans a resolution and target ball count within the kits (after a run
   * that missed them, a smaller one); the form takes them. A size asked is the largest one wanted.
   * @returns {Promise<object|null>} the plan, or null with the reason on the line
   */
  async fitMyKits() {
    const out = this.el('kit-fit');
    const { have, error } = this.owned();
    const fail = (message) => {
      out.textContent = message;
      this.lastFit = null;
      return null;
    };
    if (error) return fail(error);
    if (!have) return fail('Choose the kits you own first (how many of each).');
    if (!this.fitKitsFn) return fail('The core is not ready yet.');
    const bound = this.sizeMode() && this.lastEstimate?.resolution > 0 ? this.lastEstimate.resolution : 0;
    const sizeLimit = bound ? { cm: checkSize(this.el('size-cm').value).cm, resolution: bound } : null;
    let plan;
    try {
      plan = await this.fitKitsFn(have, bound, this.kitsMissed);
    } catch (err) {
      return fail(err.message);
    }
    this.lastFit = plan;
    if (plan.possible) this.set({ resolution: plan.resolution, target_nodes: plan.target_nodes });
    this.fitText = fitPlanText(plan, sizeLimit);
    out.textContent = this.fitText;
    return plan;
  }

  /**
   * Run and Cancel swap. A disabled button loses the keyboard focus to the page body, so the focus
   * moves to the one that is enabled now (Run → Cancel, and back when the run ends).
   */
  setRunning(running) {
    const [from, to] = running ? [this.el('run'), this.el('cancel')] : [this.el('cancel'), this.el('run')];
    const hadFocus = globalThis.document?.activeElement === from;
    to.disabled = false;
    from.disabled = true;
    if (hadFocus) to.focus();
  }

  scheduleEstimate() {
    clearTimeout(this.estimateTimer);
    if (this.held > 0) {
      this.heldEstimate = true;
      return;
    }
    this.estimateTimer = setTimeout(() => this.updateEstimate(), 200);
  }

  /**
   * Runs `work` (the app putting up a shape and its model in several steps) with the estimate held
   * until it settles, then asks for one: an estimate from a step in between would be for settings
   * about to change, and would keep the core busy meanwhile.
   */
  async holdEstimates(work) {
    this.held = (this.held || 0) + 1;
    try {
      return await work();
    } finally {
      if (--this.held === 0 && this.heldEstimate) {
        this.heldEstimate = false;
        clearTimeout(this.estimateTimer);
        this.updateEstimate(); // at once: before the requests that follow the shape (the warm-up)
      }
    }
  }

  /** Z0 at the chosen resolution: the model's bill, and the advisor's suggestion. */
  async updateEstimate() {
    const serial = ++this.estimateSerial;
    const resolution = Number(this.el('resolution').value);
    const target = Math.max(0, Math.round(Number(this.el('target').value) || 0)); // the kits are for the run's ball target
    let e;
    try {
      if (this.sizeMode()) {
        const { cm, error } = checkSize(this.el('size-cm').value);
        if (error) {
          this.showEstimate(null, resolution);
          this.el('estimate').textContent = error;
          return;
        }
        e = await this.estimateSizeFn(cm, target);
        if (serial !== this.estimateSerial) return;
        this.showEstimate(e, e.resolution);
        return;
      }
      // The line names no kits beside the model made at this resolution: the kits' quick pass waits.
      e = await this.estimateFn(resolution, target, { kits: !this.showsResult(resolution) });
    } catch (err) {
      // No mesh loaded: clear the line and the last mesh's warning with it. Busy with a run: the
      // line still describes the model being made.
      if (serial === this.estimateSerial && !/in progress/.test(err?.message)) {
        this.showEstimate(null, resolution);
        if (this.sizeMode() && !/no mesh/.test(err?.message)) this.el('estimate').textContent = err.message; // the core's range
      }
      return;
    }
    if (serial !== this.estimateSerial) return;
    this.showEstimate(e, resolution);
  }

  /** A run on this shape took `seconds` besides its time: the line under the time says so. */
  setMeasuredSetup(seconds) {
    this.measuredSetup = seconds > 0 ? seconds : 0;
    this.showSetup(this.lastEstimate);
  }

  showSetup(e) {
    const note = this.el('time-note');
    if (note) note.textContent = setupText(setupSeconds(e, this.measuredSetup), this.measuredSetup > 0);
  }

  /** The estimate line and, when the genus is lost, the advice with a button for its resolution. */
  showEstimate(e, resolution) {
    const out = this.el('estimate');
    const warn = this.el('advice');
    this.lastEstimate = e ? { ...e, resolution } : null;
    this.showSetup(this.lastEstimate);
    warn.textContent = '';
    if (!e) {
      out.textContent = '';
      this.showKitFit(null);
      warn.replaceChildren();
      warn.hidden = true;
      return;
    }
    const target = Number(this.el('target').value) || e.nodes;
    this.showKitFit(e);
    const asked = this.sizeMode() && e.size_cm ? `At ${e.size_cm} cm (about ${e.resolution} cells):` : '';
    // The automatic choice's sentence is said once: with the bill, or as the warning when no grid
    // keeps the holes (then there is no other advice and no "run anyway" to tick).
    const lost = !e.kept && this.autoMessage && this.noKeepingGrid;
    const shown = this.showsResult(resolution);
    // An estimate made without its kits (for the model on screen) is asked again when it must name them.
    if (!shown && !('kit_plan' in e) && !this.sizeMode()) this.scheduleEstimate();
    const bill = shown ? `The model on screen was made at ${resolution} cells; its parts and kit plan are under Parts.`
      : estimateText(e, target) + (isLarge(e) ? ' — a very large build.' : '');
    out.textContent = [lost ? '' : this.autoMessage, asked, bill].filter(Boolean).join(' ');
    warn.replaceChildren();
    warn.hidden = e.kept;
    if (e.kept) return;
    if (lost) {
      warn.append(this.autoMessage);
      return;
    }
    warn.append(adviceText(e, resolution) + '.');
    if (e.advice_resolution > 0 && e.advice_resolution !== resolution) this.appendSuggestion(warn, e.advice_resolution);
    const consent = document.createElement('label');
    const box = Object.assign(document.createElement('input'), { type: 'checkbox', id: 'genus-consent',
      checked: this.genusConsent });
    box.addEventListener('change', () => { this.genusConsent = box.checked; });
    consent.append(box, ' run anyway');
    warn.append(' ', consent);
  }

  /** A button that moves the slider to `resolution`, labelled with what that model would cost. */
  async appendSuggestion(warn, resolution) {
    const button = Object.assign(document.createElement('button'), { type: 'button', id: 'use-advice',
      textContent: `Use ${resolution} cells` });
    button.addEventListener('click', () => this.set({ resolution }));
    warn.append(' ', button);
    try {
      const e = await this.estimateFn(resolution);
      button.textContent = `Use ${resolution} cells (${billText(e)})`;
      if (isLarge(e)) {
        button.classList.add('large');
        button.title = 'A very large build: check the size and the kits before buying parts.';
        button.textContent += ' — very large';
      }
    } catch {
      // The label keeps the resolution alone.
    }
  }
}
