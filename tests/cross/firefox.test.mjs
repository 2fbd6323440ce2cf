// Cross-engine smoke suite in Firefox (firefox-esr + puppeteer-core, WebDriver BiDi). See smoke.mjs.
import { smokeSuite } from './smoke.mjs';

smokeSuite('firefox');
