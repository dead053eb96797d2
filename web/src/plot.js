// Progress while running: a bar (time against the budget), in plain words what is happening and
// how close the model is so far, the technical figures (temperature, energy, proposals) one click
// away, and a live energy plot (uPlot).
import uPlot from 'uplot';

const STATE_WORDS = { initial: 'building the first model', annealing: 'improving the model', done: 'done',
  cancelled: 'cancelled', failed: 'failed', idle: 'idle' };

/** The progress line a hobbyist reads: what, how long, how big, how close so far. */
export function progressText(p) {
  const budget = p.budget_seconds || 0;
  const parts = [STATE_WORDS[p.state] || p.state, `${p.seconds.toFixed(1)} s${budget ? ` of ${budget} s` : ''}`,
    `${p.nodes} balls, ${p.struts} struts`];
  if (p.gap_mm > 0) {
    const sofar = p.state === 'annealing' ? ' so far' : '';
    parts.push(`largest gap ${Math.round(p.gap_mm)} mm${sofar}, typical ${p.rms_mm.toFixed(1)} mm`);
  }
  return parts.join(' · ');
}

/** The figures behind it, for those who want them. */
export function technicalText(p) {
  const parts = [];
  if (p.state === 'annealing' || p.commits) {
    parts.push(`temperature ${p.temperature.toExponential(2)}`, `energy ${p.energy.toFixed(4)}`);
  }
  if (p.proposals) parts.push(`${p.proposals} proposals, ${p.commits} commits`);
  if (p.threads) parts.push(`${p.threads} thread${p.threads > 1 ? 's' : ''}`);
  return parts.join(' · ');
}

export class RunPlot {
  constructor(root) {
    this.bar = root.querySelector('#progress-bar');
    this.text = root.querySelector('#progress-text');
    this.tech = root.querySelector('#progress-tech');
    this.plotBox = root.querySelector('#energy-plot');
    this.times = [];
    this.energies = [];
    this.held = false; // Cancel was pressed: the bar stays where the run got to
    this.plot = new uPlot({
      width: 300, height: 140, legend: { show: false }, cursor: { show: false },
      scales: { x: { time: false } },
      axes: [{ stroke: '#aab', grid: { stroke: '#333a' } }, { stroke: '#aab', grid: { stroke: '#333a' }, size: 44 }],
      series: [{}, { label: 'energy', stroke: '#f2c20f', width: 1.5 }],
    }, [[], []], this.plotBox);
    new ResizeObserver(() => {
      const w = this.plotBox.clientWidth;
      if (w) this.plot.setSize({ width: w, height: 140 });
    }).observe(this.plotBox);
  }

  reset() {
    this.times = [];
    this.energies = [];
    this.plot.setData([[], []]);
    this.bar.value = 0;
    this.held = false;
    this.text.textContent = '';
    if (this.tech) this.tech.textContent = '';
  }

  /**
   * Cancel pressed: later reports no longer move the bar (the annealer's last report of a stopped
   * run says fraction 1, which would show a cancelled run as complete).
   */
  hold() {
    this.held = true;
  }

  /** @param {import('./protocol.js').Progress} p */
  update(p) {
    const annealing = p.state === 'annealing';
    this.bar.max = 1;
    if (!this.held) this.bar.value = p.state === 'done' ? 1 : Math.min(1, p.fraction || 0);
    this.text.textContent = progressText(p);
    if (this.tech) this.tech.textContent = technicalText(p);
    if (annealing && Number.isFinite(p.energy) && p.energy > 0) {
      this.times.push(p.seconds);
      this.energies.push(p.energy);
      this.plot.setData([this.times, this.energies]);
    }
  }
}
