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

/** How far a fix reaches: three B1 lengths (docs/work-on-a-model.md has the measurements). */
export const FIX_RADIUS_B1 = 3;
const B1_MM = 74.86; // core/zome/real_sizes.h

/** The spot a fix changes around `at` (mesh units), or null without the model's scale. */
export function spotAround(at, summary) {
  const b1 = summary?.stats?.b1_mesh_units;
  if (!Array.isArray(at) || at.length !== 3 || !(b1 > 0)) return null;
  return { near: at.map(Number), radius: FIX_RADIUS_B1 * b1 };
}

/** The spot of "Fix the largest gap": the gap the quality line names. */
export function gapSpot(summary) {
  return spotAround(summary?.stats?.fidelity?.largest_gap?.at, summary);
}

/**
 * Why More detail is off: the model already has as many balls as the shape holds well at its size
 * (the core's figure and sentence, `capacity_full` of the summary: issue 40), or ''.
 */
export function capacityFull(summary) {
  const text = summary?.capacity_full;
  return typeof text === 'string' && text ? text[0].toUpperCase() + text.slice(1) + '.' : '';
}

/** What the note says after a step: balls and largest gap before and after. */
export function stepText(label, before, after) {
  const gap = (s) => s?.stats?.fidelity?.hausdorff_mm;
  const mm = (v) => (Number.isFinite(v) ? `${Math.round(v)} mm` : 'not measured');
  const c = after.stats?.continued;
  const short = c?.short_of_target
    ? `; it reached ${after.balls} of the ${c.target_nodes} balls asked: at this size the model cannot change more this way`
    : '';
  const capped = c?.capped && c.capacity_note ? ' ' + c.capacity_note : ''; // the core's sentence
  return `${label}: ${before.balls} → ${after.balls} balls, largest gap ${mm(gap(before))} → ${mm(gap(after))}` +
    (c?.kept_as_it_was ? ' (nothing better found: the model is as it was)' : '') + short +
    '.' + capped + ' Undo puts the previous model back.';
}

const LABELS = { improve: 'Improve', fewer: 'Fewer balls', more: 'More detail', fix: 'Fix the largest gap',
  here: 'Fix here' };

export class ModelWork {
  /** @param {Document|HTMLElement} root  @param {{app: object, bridge: object}} deps */
  constructor(root, { app, bridge }) {
    this.root = root;
    this.app = app;
    this.bridge = bridge;
    this.undoStack = []; // .zome.json bytes of the models before each step
    this.spot = null;    // a point of the surface clicked in the viewer (mesh units), for Fix here
    for (const kind of Object.keys(LABELS)) this.el(kind)?.addEventListener('click', () => this.step(kind));
    this.el('undo')?.addEventListener('click', () => this.undo());
    this.refresh();
  }

  el(name) { return this.root.querySelector?.('#work-' + name) ?? null; }

  /** The buttons follow the model on screen: a valid model of the loaded shape, no run going. */
  refresh() {
    const s = this.app.shownSummary;
    const ofMesh = this.app.modelOfSurface || this.app.modelAfterMesh;
    const ready = Boolean(s && s.valid && ofMesh && !this.app.running);
    const hint = 'To work on this model (Improve, Fewer balls, …), drop the mesh it was made from, then the model.';
    if (s?.valid && !ofMesh && !this.app.running) this.note(hint);
    else if (this.el('note')?.textContent === hint) this.note('');
    // More detail on a model that has the balls its shape holds well at this size would make it
    // worse: the button is off and says why (its title, and the note when it says nothing else).
    const full = ready ? capacityFull(s) : '';
    for (const kind of Object.keys(LABELS)) {
      const b = this.el(kind);
      if (b) {
        b.disabled = !ready || (kind === 'fix' && !gapSpot(s)) || (kind === 'here' && !spotAround(this.spot, s)) ||
          (kind === 'more' && Boolean(full));
      }
    }
    const more = this.el('more');
    if (more) {
      this.moreTitle ??= more.title ?? ''; // the page's own title, put back when it applies again
      more.title = full || this.moreTitle;
    }
    if (full && !this.el('note')?.textContent) this.note(full);
    else if (!full && this.el('note')?.textContent === this.fullShown) this.note('');
    this.fullShown = full;
    const undo = this.el('undo');
    if (undo) undo.disabled = this.app.running || this.undoStack.length === 0;
  }

  /** Continues the model on screen; the model before it goes on the undo stack. */
  async step(kind) {
    const before = this.app.shownSummary;
    if (!before || this.app.running) return null;
    if (kind === 'more' && capacityFull(before)) { // the core would refuse it (window.zomeify.workOn)
      this.note(capacityFull(before));
      return null;
    }
    const saved = (await this.bridge.exportModel('before.zome.json')).bytes;
    const fix = kind === 'fix' || kind === 'here';
    const extra = { continue: true, target_nodes: fix ? 0 : stepTarget(kind, before.balls) };
    if (kind === 'fix') Object.assign(extra, gapSpot(before));
    if (kind === 'here') Object.assign(extra, spotAround(this.spot, before));
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
    await this.bridge.load('before.zome.json', bytes.slice().buffer); // an ArrayBuffer, handed to the worker
    this.app.modelOfSurface = true; // it was made for the shape loaded
    await this.app.refreshResults();
    this.note(`Back to the previous model (${this.app.shownSummary?.balls ?? '?'} balls).`);
    this.refresh();
  }

  /** A point of the surface was clicked: Fix here will change the model around it. */
  setSpot(point) {
    this.spot = point;
    this.refresh();
    if (this.app.shownSummary && this.app.modelOfSurface) {
      this.note(`Spot chosen: Fix here changes only the model within about ${Math.round(FIX_RADIUS_B1 * B1_MM / 10)} cm ` +
        'of it (click the shape elsewhere to choose another).');
    }
  }

  note(text) {
    const el = this.el('note');
    if (el) el.textContent = text;
  }
}
