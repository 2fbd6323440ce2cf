// ro texts of SplineLab, part "demos" (merged in www/lang/ro.js). English text → translation; a plural entry is keyed
// by the English plural and holds the CLDR forms { one, few, many, other } (www/lib/i18n.js).
export default {
};
