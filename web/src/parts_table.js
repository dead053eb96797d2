// The parts list and kit plan as a table. Hovering or focusing (Tab) a strut row highlights those
// struts in the viewer (onHover(kindIds | null)).
import { KIND_NAMES } from './protocol.js';

export const SWATCH = { blue: '#1f5fd6', yellow: '#f2c20f', red: '#d42a1e', white: '#f4f4f4' };

// The table's text, kept pure (no DOM) so web/tests/ can check it.

/** Rows in the report's order: the ball first, then each strut kind that is used (count > 0). */
export function partRows(report) {
  const rows = [{ part: report.ball_part_code, kind: 'ball', length: '17.67', count: report.balls,
    color: 'white', kindIds: null }];
  for (const k of report.kinds) {
    if (!k.count) continue;
    rows.push({ part: k.part_code, kind: k.kind, length: k.length_mm.toFixed(2), count: k.count,
      color: k.color, kindIds: [KIND_NAMES.indexOf(k.kind)] });
  }
  return rows;
}

/** "226 balls, 577 struts, 38.11 m of struts; built size 49.0 × 46.7 × 45.3 cm" */
export function totalsText(report) {
  const size = report.size_cm.map((x) => x.toFixed(1)).join(' × ');
  return `${report.balls} balls, ${report.strut_count} struts, ` +
    `${(report.total_strut_length_mm / 1000).toFixed(2)} m of struts; built size ${size} cm`;
}

/** "Kit plan: 2 × Creator 3 + 1 × Basic (1845 parts bought)"; "none" when no kit is needed. */
export function kitPlanText(plan) {
  const kits = plan.kits.map((k) => `${k.count} × ${k.name}`).join(' + ') || 'none';
  return `Kit plan: ${kits} (${plan.parts_bought} parts bought)`;
}

/**
 * A mirror-symmetric model's parts by half (core/parts/mirror_halves.h): "Mirror-symmetric: build one
 * half (173 balls, 443 struts) twice, the second mirrored, then the middle (24 balls, 36 struts)
 * on the plane or across it." '' for any other model.
 */
export function halvesText(mirror) {
  if (!mirror) return '';
  const part = (c) => `${c.balls} balls, ${c.strut_count} struts`;
  return `Mirror-symmetric: build one half (${part(mirror.half)}) twice, the second mirrored, then the middle ` +
    `(${part(mirror.middle)}) on the plane or across it.`;
}

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
    this.halves = root.querySelector('#parts-halves');
    this.onHover = onHover;
    this.report = null;
  }

  clear() {
    this.report = null;
    this.table.replaceChildren();
    this.totals.textContent = '';
    this.kits.textContent = '';
    if (this.halves) this.halves.textContent = '';
  }

  /** @param {object} report parts_report_json (core/parts/parts_report.h) */
  show(report) {
    this.report = report;
    const head = document.createElement('tr');
    for (const h of ['part', 'kind', 'length mm', 'count']) head.append(cell('th', h));
    const rows = [head];
    for (const r of partRows(report)) {
      const tr = document.createElement('tr');
      const kindCell = cell('td', r.kind);
      if (r.kindIds) {
        const swatch = cell('span', '', 'swatch');
        swatch.style.background = SWATCH[r.color];
        kindCell.prepend(swatch);
        const on = () => { tr.classList.add('hover'); this.onHover(r.kindIds); };
        const off = () => { tr.classList.remove('hover'); this.onHover(null); };
        tr.addEventListener('mouseenter', on);
        tr.addEventListener('mouseleave', off);
        // Keyboard users reach the same highlight with Tab.
        tr.tabIndex = 0;
        tr.addEventListener('focus', on);
        tr.addEventListener('blur', off);
      }
      tr.append(cell('td', r.part), kindCell, cell('td', r.length), cell('td', r.count, 'n'));
      tr.dataset.kind = r.kind;
      rows.push(tr);
    }
    this.table.replaceChildren(...rows);
    this.totals.textContent = totalsText(report);
    this.kits.textContent = kitPlanText(report.kit_plan);
    if (this.halves) this.halves.textContent = halvesText(report.mirror);
  }
}
