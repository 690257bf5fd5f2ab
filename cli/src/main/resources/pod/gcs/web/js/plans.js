// Pod ground station: the plans panel.

/** Called once at start with the page's app (see app.js). */
export function init(app) {}
