// The parts list and kit plan as a table. Hovering a strut row highlights those struts in the
// viewer (onHover(kindIds | null)).
import { KIND_NAMES } from './protocol.js';

const SWATCH = { blue: '#1f5fd6', yellow: '#f2c20f', red: '#d42a1e', white: '#f4f4f4' };

function cell(tag, text, cls) {
  const e = document.createElement(tag);
  e.textContent = text;
  if (cls) e.className = cls;
  return e;
}

export class PartsTable {
  constructor(root, { onHover }) {
    this.table = root.querySelector('#parts-table');
    this.totals = root.querySelector('#parts-totals');
    this.kits = root.querySelector('#kit-plan');
    this.onHover = onHover;
    this.report = null;
  }

  clear() {
    this.report = null;
    this.table.replaceChildren();
    this.totals.textContent = '';
    this.kits.textContent = '';
  }

  /** @param {object} report parts_report_json (core/parts/parts_report.h) */
  show(report) {
    this.report = report;
    const head = document.createElement('tr');
    for (const h of ['part', 'kind', 'length mm', 'count']) head.append(cell('th', h));
    const rows = [head];
    const ball = document.createElement('tr');
    ball.append(cell('td', report.ball_part_code), cell('td', 'ball'), cell('td', '17.67'), cell('td', report.balls, 'n'));
    ball.dataset.kind = 'ball';
    rows.push(ball);
    for (const k of report.kinds) {
      if (!k.count) continue;
      const tr = document.createElement('tr');
      const kindCell = cell('td', k.kind);
      const swatch = cell('span', '', 'swatch');
      swatch.style.background = SWATCH[k.color];
      kindCell.prepend(swatch);
      tr.append(cell('td', k.part_code), kindCell, cell('td', k.length_mm.toFixed(2)), cell('td', k.count, 'n'));
      tr.dataset.kind = k.kind;
      const ids = [KIND_NAMES.indexOf(k.kind)];
      tr.addEventListener('mouseenter', () => { tr.classList.add('hover'); this.onHover(ids); });
      tr.addEventListener('mouseleave', () => { tr.classList.remove('hover'); this.onHover(null); });
      rows.push(tr);
    }
    this.table.replaceChildren(...rows);
    const size = report.size_cm.map((x) => x.toFixed(1)).join(' × ');
    this.totals.textContent = `${report.balls} balls, ${report.strut_count} struts, ` +
      `${(report.total_strut_length_mm / 1000).toFixed(2)} m of struts; built size ${size} cm`;
    const plan = report.kit_plan;
    const kits = plan.kits.map((k) => `${k.count} × ${k.name}`).join(' + ') || 'none';
    this.kits.textContent = `Kit plan: ${kits} (${plan.parts_bought} parts bought)`;
  }
}
