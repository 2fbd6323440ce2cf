// Indices as a reader reads them (issue 25: no ASCII subscript notation in anything shown or spoken): Unicode
// subscripts and superscripts of an integer, for names like W₋₁, P₃, N₂,₃ and orders like C², C⁻¹. The one place
// for them (the demos had nine copies of the subscript, some without the minus sign).

/** Unicode subscripts of an integer (or an integer-like string): 3 → ₃, −1 → ₋₁. @param {number | string} i */
export const subscript = (i) => String(i).replace(/[-−]/g, '₋').replace(/\d/g, (d) => '₀₁₂₃₄₅₆₇₈₉'[Number(d)]);

/** Unicode superscripts of an integer: 2 → ², −1 → ⁻¹. @param {number | string} i */
export const superscript = (i) => String(i).replace(/[-−]/g, '⁻').replace(/\d/g, (d) => '⁰¹²³⁴⁵⁶⁷⁸⁹'[Number(d)]);
