// Progress while running: a bar (time against the budget), temperature and counts, and a live
// energy plot (uPlot).
import uPlot from 'uplot';

export class RunPlot {
  constructor(root) {
    this.bar = root.querySelector('#progress-bar');
    this.text = root.querySelector('#progress-text');
    this.plotBox = root.querySelector('#energy-plot');
    this.times = [];
    this.energies = [];
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
    this.text.textContent = '';
  }

  /** @param {import('./protocol.js').Progress} p */
  update(p) {
    const budget = p.budget_seconds || 0;
    const annealing = p.state === 'annealing';
    this.bar.max = 1;
    this.bar.value = p.state === 'done' ? 1 : Math.min(1, p.fraction || 0);
    const parts = [`${p.state}`, `${p.seconds.toFixed(1)} s${budget ? ` / ${budget} s` : ''}`];
    if (annealing || p.commits) parts.push(`T ${p.temperature.toExponential(2)}`, `E ${p.energy.toFixed(4)}`);
    parts.push(`${p.nodes} balls`, `${p.struts} struts`);
    if (p.threads) parts.push(`${p.threads} thread${p.threads > 1 ? 's' : ''}`);
    this.text.textContent = parts.join(' · ');
    if (annealing && Number.isFinite(p.energy) && p.energy > 0) {
      this.times.push(p.seconds);
      this.energies.push(p.energy);
      this.plot.setData([this.times, this.energies]);
    }
  }
}
