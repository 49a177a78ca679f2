// The review page's controls (src/app/check/review_page.cpp). It reads only the page's own elements and
// attributes: no data reaches it as code, and it loads nothing.
'use strict';
(() => {
  for (const viewer of document.querySelectorAll('.viewer')) {
    const set = (name, value) => viewer.style.setProperty(name, value);
    for (const radio of viewer.querySelectorAll('input[type=radio]'))
      radio.addEventListener('change', () => { if (radio.checked) viewer.dataset.mode = radio.value; });
    const split = viewer.querySelector('input.split');
    if (split) split.addEventListener('input', () => set('--split', split.value + '%'));
    const blend = viewer.querySelector('input.blend');
    if (blend) blend.addEventListener('input', () => set('--blend', String(blend.value / 100)));
    const zoom = viewer.closest('.case').querySelector('select.zoom');
    if (zoom) zoom.addEventListener('change', () => viewer.closest('.case').style.setProperty('--zoom', zoom.value));
  }

  // j / k: the next / previous case that fails the run, in page order (failures come first).
  const failing = Array.from(document.querySelectorAll('section.case[data-fails-run="1"]'));
  let current = -1;
  const show = (index) => {
    if (failing.length === 0) return;
    current = (index + failing.length) % failing.length;
    for (const c of failing) c.classList.toggle('current', c === failing[current]);
    failing[current].focus({preventScroll: true});
    failing[current].scrollIntoView({block: 'start'});
  };
  document.addEventListener('keydown', (event) => {
    if (event.ctrlKey || event.metaKey || event.altKey) return;
    const tag = event.target && event.target.tagName;
    if (tag === 'INPUT' && event.target.type !== 'radio' || tag === 'SELECT' || tag === 'TEXTAREA') return;
    if (event.key === 'j') show(current + 1);
    else if (event.key === 'k') show(current < 0 ? failing.length - 1 : current - 1);
    else return;
    event.preventDefault();
  });
})();
