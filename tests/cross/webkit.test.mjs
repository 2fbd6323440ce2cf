// Cross-engine smoke suite in WebKit (WebKitGTK MiniBrowser + WebKitWebDriver + webdriverio). See smoke.mjs.
import { smokeSuite } from './smoke.mjs';

smokeSuite('webkit');
