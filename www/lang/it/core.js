// it texts of SplineLab, part "core" (merged in www/lang/it.js). English text → translation; a plural entry is keyed
// by the English plural and holds the CLDR forms { one, few, many, other } (www/lib/i18n.js).
export default {
};
