// The curve tab's numbers: the curvature at the breakpoints (K by (13), K* by the corrected (14), measured, the
// right-sided (15) and (15) as printed), the jumps of g*⁽ⁱ⁾ at the joints, and a status line on the Cʳ
// conditions (8).
import { h, fmt, clear, append } from '../../lib/dom.js';
import { table } from '../../lib/controls.js';
import { sub, sup, sci } from './notation.js';

/** curveTables() → { curvature, jumps, status (elements), refresh(state, res) }. */
export function curveTables() {
  const curvTable = table({ caption: 'Curvature at the breakpoints', columns: ['I', 'K (13)', 'K* (14)', 'K* measured', 'K* (15) right-sided', '(15) printed'], digits: 5 });
  curvTable.el.dataset.role = 'curvature';
  const contTable = table({ caption: 'Jumps of g*⁽ⁱ⁾ at the joints', columns: ['I'], digits: 3 });
  const status = h('p', { class: 'ctl-hint', 'aria-live': 'polite' });
  let headKey = '';

  function refresh(state, res) {
    if (!res) return;
    const rows = [];
    for (let i = 0; i < res.curvature.length; i++) {
      rows.push([`u${sub(i)} = ${fmt(state.breaks[i], 3)}`, res.curvatureOriginal[i], res.curvature[i], res.curvatureMeasured[i], res.curvaturePredicted[i], res.curvaturePrinted[i]]);
    }
    curvTable.set(rows);
    const r = state.r;
    const cols = ['I'];
    for (let i = 0; i <= r + 1; i++) cols.push(`d${sub(i)}${i <= r ? '' : ' (r+1)'}`);
    // the header changes with r only (not in a drag frame)
    if (cols.join('|') !== headKey) {
      headKey = cols.join('|');
      const head = contTable.el.querySelector('thead tr');
      clear(head);
      append(head, cols.map((c) => h('th', { scope: 'col' }, c)));
    }
    contTable.set(Array.from(res.continuity, (row, j) => [String(j + 1), ...Array.from(row, sci)]));
    // the largest jump of the orders ≤ r, relative to the API's scale of each order
    const scale = res.continuityScale;
    let worst = 0;
    for (const row of res.continuity) for (let i = 0; i <= r; i++) worst = Math.max(worst, row[i] / scale[i]);
    const origRes = res.crResidualOriginal;
    status.textContent = `g is degree ${state.degree} on ${state.breaks.length - 1} segments; g* has degree ${state.degree + 1}. ` +
      `C${sup(r)} conditions (8): residual ${sci(res.crResidual)} (g: ${sci(origRes)}); largest relative jump of orders ≤ r: ${sci(worst)} — ` +
      (worst < 1e-9 ? `g* is C${sup(r)} ✓` : `g* is not C${sup(r)}`) + '.';
  }

  return { curvature: curvTable.el, jumps: contTable.el, status, refresh };
}
