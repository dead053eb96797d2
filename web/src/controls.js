// The run controls: resolution with a live estimate (and the advisor's warning), time presets,
// target complexity, threads, advanced weights and seed. Reads them as protocol RunOptions.
export const PRESETS = { quick: 5, standard: 30, thorough: 120 };
// The core's defaults replace these weights at start-up (setDefaults), so the page runs what the CLI does.
const DEFAULTS = { resolution: 12, preset: 'quick', seconds: 5, target_nodes: 0, threads: 0, seed: 1,
  weights: { dist: 30, orient: 100, fair: 5, complex: 1, surface: 100, fold: 1 } };

// The controls' arithmetic and text, kept pure (no DOM) so web/tests/ can check it.

/** The preset whose time is `seconds`, else 'custom'. */
export function presetForSeconds(seconds) {
  return Object.keys(PRESETS).find((k) => PRESETS[k] === seconds) || 'custom';
}

/** "auto" threads: all cores but one, at least 1, at most maxThreads. */
export function autoThreadCount(cores, maxThreads) {
  return Math.max(1, Math.min((cores || 2) - 1, maxThreads));
}

/** The estimate line: Z0's counts, and the final model's (target balls, 2.2–2.9 struts per ball). */
export function estimateText(e, target) {
  return `Z0: ${e.nodes} balls, ${e.struts} struts · final ≈ ${target} balls, ` +
    `${Math.round(2.2 * target)}–${Math.round(2.9 * target)} struts`;
}

/** The advisor's warning ('' when Z0 keeps the surface's genus). */
export function adviceText(e, resolution) {
  return e.kept ? '' : (e.advice || `at ${resolution} cells the model's genus is ${e.genus}, ` +
    `the surface's ${e.surface_genus}`);
}

export class Controls {
  /** @param {HTMLElement} root @param {{estimate: (r:number)=>Promise<object>}} deps */
  constructor(root, { estimate }) {
    this.root = root;
    this.estimateFn = estimate;
    this.el = (id) => root.querySelector('#' + id);
    this.maxThreads = 1;
    this.estimateTimer = null;
    this.estimateSerial = 0;
    this.initialOnly = false; // API only: stop after Z0

    this.el('resolution').addEventListener('input', () => {
      this.el('resolution-value').textContent = this.el('resolution').value;
      this.scheduleEstimate();
    });
    this.el('preset').addEventListener('change', () => this.presetChanged());
    this.set(DEFAULTS);
  }

  /** The core's default weights (from the wasm module): the form's starting values. */
  setDefaults(defaults) {
    if (!defaults || !defaults.weights) return;
    for (const k of Object.keys(DEFAULTS.weights)) {
      if (Number.isFinite(defaults.weights[k])) DEFAULTS.weights[k] = defaults.weights[k];
    }
    this.set({ weights: DEFAULTS.weights });
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
      this.el('resolution').value = o.resolution;
      this.el('resolution-value').textContent = String(o.resolution);
      this.scheduleEstimate();
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
      weights: Object.fromEntries(Object.keys(DEFAULTS.weights).map((k) => [k, num('w-' + k, DEFAULTS.weights[k])])),
    };
  }

  setRunning(running) {
    this.el('run').disabled = running;
    this.el('cancel').disabled = !running;
  }

  scheduleEstimate() {
    clearTimeout(this.estimateTimer);
    this.estimateTimer = setTimeout(() => this.updateEstimate(), 200);
  }

  /** Z0 at the chosen resolution: nodes now, and the rough size of the final model. */
  async updateEstimate() {
    const serial = ++this.estimateSerial;
    const out = this.el('estimate');
    const warn = this.el('advice');
    const resolution = Number(this.el('resolution').value);
    let e;
    try {
      e = await this.estimateFn(resolution);
    } catch {
      // No estimate (e.g. no mesh loaded): clear the line and the last mesh's warning with it.
      if (serial === this.estimateSerial) {
        out.textContent = '';
        warn.textContent = '';
        warn.hidden = true;
      }
      return;
    }
    if (serial !== this.estimateSerial) return;
    const target = Number(this.el('target').value) || e.nodes;
    out.textContent = estimateText(e, target);
    warn.textContent = adviceText(e, resolution);
    warn.hidden = e.kept;
  }
}
