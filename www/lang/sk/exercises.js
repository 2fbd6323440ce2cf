// sk texts of SplineLab, part "exercises" (merged in www/lang/sk.js). English text → translation; a plural entry is keyed
// by the English plural and holds the CLDR forms { one, few, many, other } (www/lib/i18n.js).
export default {
};
