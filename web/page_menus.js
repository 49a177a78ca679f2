// The panel's menus, built from the program's tables (shadelab_tables `menus`, web/tables.cpp) instead of
// typed into index.html: each <select> gets one option per value of its C++ vocabulary, in its order, the
// value its spelling and the label the lecture's words for it with the key that chooses it; the key that
// steps through a menu follows it. A value added to a C++ table shows up here without editing the page.
'use strict';

// Called once the tables are there (page_core.js), before the panel's first refresh selects a value.
function fillMenus(menus) {
  for (const [id, menu] of Object.entries(menus)) {
    const select = $(id);
    if (!select) continue; // a table with no menu on the page
    select.replaceChildren();
    for (const value of menu.options) {
      const option = new Option(value.key ? value.label + ' (' + value.key + ')' : value.label, value.value);
      if (value.help) option.title = value.help;
      select.add(option);
    }
    const hint = select.parentElement.querySelector('.menu-key');
    if (hint) hint.textContent = menu.key ? '(' + menu.key + ')' : '';
  }
}
