// Working on the model on screen (issue 40; the paper's §6): Improve, Fewer balls and More detail
// continue it in the core at its own size (run options `continue` and `target_nodes`), Fix the
// largest gap changes only the part near the gap (`near`, `radius`), and Undo puts back the model
// before the last of them, so a worse result costs nothing.

/** Each step's ball target against the model's balls (the paper's hierarchies: −25 %, +30 %). */
export const STEP_FACTORS = { improve: 1, fewer: 0.75, more: 1.3 };

/** The ball target of a step from a model of `balls` balls (at least 4, the core's least). */
export function stepTarget(kind, balls) {
  return Math.max(4, Math.round(balls * STEP_FACTORS[kind]));
}

/** The spot a fix changes: the largest gap, within three B1 lengths (mesh units) of it (docs/work-on-a-model.md). */
export function gapSpot(summary) {
  const at = summary?.stats?.fidelity?.largest_gap?.at;
  const b1 = summary?.stats?.b1_mesh_units;
  if (!Array.isArray(at) || at.length !== 3 || !(b1 > 0)) return null;
  return { near: at, radius: 3 * b1 };
}

/** What the note says after a step: balls and largest gap before and after. */
export function stepText(label, before, after) {
  const gap = (s) => s?.stats?.fidelity?.hausdorff_mm;
  const mm = (v) => (Number.isFinite(v) ? `${Math.round(v)} mm` : 'not measured');
  return `${label}: ${before.balls} → ${after.balls} balls, largest gap ${mm(gap(before))} → ${mm(gap(after))}` +
    (after.stats?.continued?.kept_as_it_was ? ' (nothing better found: the model is as it was)' : '') +
    '. Undo puts the previous model back.';
}

const LABELS = { improve: 'Improve', fewer: 'Fewer balls', more: 'More detail', fix: 'Fix the largest gap' };

export class ModelWork {
  /** @param {Document|HTMLElement} root  @param {{app: object, bridge: object}} deps */
  constructor(root, { app, bridge }) {
    this.root = root;
    this.app = app;
    this.bridge = bridge;
    this.undoStack = []; // .zome.json bytes of the models before each step
    for (const kind of Object.keys(LABELS)) this.el(kind)?.addEventListener('click', () => this.step(kind));
    this.el('undo')?.addEventListener('click', () => this.undo());
    this.refresh();
  }

  el(name) { return this.root.querySelector?.('#work-' + name) ?? null; }

  /** The buttons follow the model on screen: a valid model of the loaded shape, no run going. */
  refresh() {
    const s = this.app.shownSummary;
    const ready = Boolean(s && s.valid && this.app.modelOfSurface && !this.app.running);
    for (const kind of Object.keys(LABELS)) {
      const b = this.el(kind);
      if (b) b.disabled = !ready || (kind === 'fix' && !gapSpot(s));
    }
    const undo = this.el('undo');
    if (undo) undo.disabled = this.app.running || this.undoStack.length === 0;
  }

  /** Continues the model on screen; the model before it goes on the undo stack. */
  async step(kind) {
    const before = this.app.shownSummary;
    if (!before || this.app.running) return null;
    const saved = (await this.bridge.exportModel('before.zome.json')).bytes;
    const extra = { continue: true, target_nodes: kind === 'fix' ? 0 : stepTarget(kind, before.balls) };
    if (kind === 'fix') Object.assign(extra, gapSpot(before));
    const final = await this.app.run({}, extra);
    if (final.state !== 'failed' && final.nodes > 0) {
      this.undoStack.push(saved);
      this.note(stepText(LABELS[kind], before, this.app.shownSummary ?? before));
    }
    this.refresh();
    return final;
  }

  /** Puts back the model before the last step (the shape stays loaded). */
  async undo() {
    const bytes = this.undoStack.pop();
    if (!bytes || this.app.running) return;
    await this.bridge.load('before.zome.json', bytes.slice(0));
    this.app.modelOfSurface = true; // it was made for the shape loaded
    await this.app.refreshResults();
    this.note(`Back to the previous model (${this.app.shownSummary?.balls ?? '?'} balls).`);
    this.refresh();
  }

  note(text) {
    const el = this.el('note');
    if (el) el.textContent = text;
  }
}
