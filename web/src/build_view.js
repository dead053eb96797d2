// The Build view: the core's assembly sequence (core/build) step by step. A slider and the
// previous/next keys choose the step; the viewer draws earlier steps normally, this step's struts
// glowing and later parts faint (later balls hidden); beside it the step's parts and the running
// counts. "Print view" shows the core's printable page (one panel per step) in a frame.
// The steps come from the model alone, so a shared link shows the sender's steps.

import { Event } from './protocol.js';

// The view's text and index maps, kept pure (no DOM) so web/tests/ can check them.

/** Per strut of the snapshot and per ball, the step (0-based) that adds it; -1 if none. */
export function stepIndexMaps(plan, snapshotStruts, ballCount) {
  const key = (a, b) => (a < b ? `${a},${b}` : `${b},${a}`);
  const strutIndex = new Map();
  for (let i = 0; 2 * i < snapshotStruts.length; i++) strutIndex.set(key(snapshotStruts[2 * i], snapshotStruts[2 * i + 1]), i);
  const strutStep = new Int32Array(snapshotStruts.length / 2).fill(-1);
  const ballStep = new Int32Array(ballCount).fill(-1);
  plan.steps.forEach((step, s) => {
    for (const b of step.balls) ballStep[b] = s;
    for (const [a, b] of step.struts) {
      const i = strutIndex.get(key(a, b));
      if (i !== undefined) strutStep[i] = s;
    }
  });
  return { strutStep, ballStep };
}

/** Parts of one step as rows [{code, count}], the ball first (the core's order). */
export function stepRows(step) {
  return Object.entries(step.parts).map(([code, count]) => ({ code, count }));
}

/** Balls and struts of steps 0..k. */
export function countsThrough(plan, k) {
  let balls = 0, struts = 0;
  for (let s = 0; s <= k && s < plan.steps.length; s++) {
    balls += plan.steps[s].balls.length;
    struts += plan.steps[s].struts.length;
  }
  return { balls, struts };
}

/** "Step 3 of 41: 2 balls, 6 struts, attached to 3 balls built before." */
export function stepText(plan, k) {
  const step = plan.steps[k];
  const n = (x, word) => `${x} ${word}${x === 1 ? '' : 's'}`;
  const where = k === 0 ? 'on the table' : `attached to ${n(step.attach.length, 'ball')} built before`;
  return `Step ${k + 1} of ${plan.steps.length}: ${n(step.balls.length, 'ball')}, ${n(step.struts.length, 'strut')}, ${where}.`;
}

/** The plan's figures in words, and for a symmetric model that both halves are built alike (core plan_report). */
export function figuresText(plan) {
  const f = plan.figures;
  const halves = plan.mirror ? ' Both halves are built alike: each step adds its parts with their mirror images ' +
    `about the plane across the ${plan.mirror.axis} axis.` : '';
  return `${plan.steps.length} steps; largest overhang ${Math.round(f.max_overhang_mm)} mm; ` +
    `${Math.round(100 * f.two_strut_share)}% of steps end with every new ball on two struts.${halves}`;
}

export class BuildView {
  /** canOpen(): null, or why the view cannot open now (a run is going). */
  constructor(doc, { bridge, viewer, status, canOpen }) {
    const $ = (id) => doc.getElementById(id);
    Object.assign(this, { doc, bridge, viewer, status, canOpen });
    this.el = { toggle: $('build-toggle'), panel: $('build-panel'), slider: $('build-step'), prev: $('build-prev'),
      next: $('build-next'), text: $('build-text'), parts: $('build-parts'), totals: $('build-totals'),
      figures: $('build-figures'), print: $('build-print'), printView: $('print-view'), frame: $('print-frame'),
      printClose: $('print-close'), printNow: $('print-now') };
    this.plan = null;
    this.version = null; // of the model planned
    this.step = 0;
    bridge.on(Event.SNAPSHOT, ({ snapshot }) => {
      if (this.plan && snapshot.version !== this.version) this.close();
    });
    this.el.toggle.addEventListener('click', () => (this.plan ? this.close() : this.open().catch((e) => status.error(e.message))));
    this.el.slider.addEventListener('input', () => this.show(Number(this.el.slider.value) - 1));
    this.el.prev.addEventListener('click', () => this.show(this.step - 1));
    this.el.next.addEventListener('click', () => this.show(this.step + 1));
    this.el.print.addEventListener('click', () => this.openPrint());
    this.el.printClose.addEventListener('click', () => { this.el.printView.hidden = true; });
    this.el.printNow.addEventListener('click', () => this.el.frame.contentWindow?.print());
    doc.addEventListener('keydown', (e) => {
      if (!this.plan || e.altKey || e.ctrlKey || e.metaKey) return;
      const t = e.target;
      if (t && (t.tagName === 'INPUT' || t.tagName === 'SELECT' || t.tagName === 'TEXTAREA')) return;
      if (e.key === 'ArrowRight' || e.key === 'PageDown' || e.key === 'n') this.show(this.step + 1);
      else if (e.key === 'ArrowLeft' || e.key === 'PageUp' || e.key === 'p') this.show(this.step - 1);
      else return;
      e.preventDefault();
    });
  }

  get isOpen() { return this.plan !== null; }

  /** Plans the model on screen and shows its first step. */
  async open() {
    const blocked = this.canOpen();
    if (blocked) throw new Error(blocked);
    const [plan, snapshot] = await Promise.all([this.bridge.buildPlan('y'), this.bridge.snapshot()]);
    this.plan = plan;
    this.version = snapshot.version;
    this.maps = stepIndexMaps(plan, snapshot.struts, plan.nodes.length);
    this.el.slider.max = String(plan.steps.length);
    this.el.panel.hidden = false;
    this.el.toggle.textContent = 'Close build view';
    this.el.toggle.setAttribute('aria-expanded', 'true');
    this.el.figures.textContent = figuresText(plan);
    this.show(0);
    return plan;
  }

  close() {
    this.plan = null;
    this.el.panel.hidden = true;
    this.el.printView.hidden = true;
    this.el.toggle.textContent = 'Build view';
    this.el.toggle.setAttribute('aria-expanded', 'false');
    this.viewer.showBuildStep(null);
  }

  show(k) {
    if (!this.plan) return;
    this.step = Math.max(0, Math.min(this.plan.steps.length - 1, k));
    this.el.slider.value = String(this.step + 1);
    this.el.text.textContent = stepText(this.plan, this.step);
    this.el.parts.replaceChildren(...stepRows(this.plan.steps[this.step]).map(({ code, count }) => {
      const li = this.doc.createElement('li');
      li.textContent = `${count} × ${code}`;
      return li;
    }));
    const c = countsThrough(this.plan, this.step);
    this.el.totals.textContent = `Built so far: ${c.balls} of ${this.plan.nodes.length} balls, ` +
      `${c.struts} of ${this.maps.strutStep.length} struts.`;
    this.viewer.showBuildStep({ ...this.maps, step: this.step });
  }

  /** One panel per step with its picture and parts (the core's page), ready for print to PDF. */
  openPrint() {
    if (!this.plan) return;
    this.el.frame.srcdoc = this.plan.html;
    this.el.printView.hidden = false;
  }
}
