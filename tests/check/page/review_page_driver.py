#!/usr/bin/env python3
"""Opens a review page (shadelab review's index.html) from file:// in Debian's headless Chromium
(chromium-driver + python3-selenium, as web/driver.py) and prints one JSON object of what it saw, for
tests/check/review_page_test.cpp to judge:

  review_page_driver.py PAGE DESKTOP.png PHONE.png

Nothing here decides pass or fail: it works the page's controls with real input where the control is about
input (the pointer over the picture, a click on a mode, the j key) and reports the computed styles.
The page is data: its names reach this script only as the page's text, never as code."""
import json
import sys

from selenium import webdriver
from selenium.common.exceptions import NoAlertPresentException
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.common.action_chains import ActionChains

CHROME_ARGS = ['--headless=new', '--no-sandbox', '--disable-dev-shm-usage', '--disable-background-networking',
               '--disable-component-update', '--disable-default-apps', '--disable-sync', '--no-first-run',
               '--disable-extensions', '--window-size=1280,800', '--force-device-scale-factor=1']
TIMEOUT = 60  # seconds: one WebDriver request, page load or script

# Runs before the page's own script: every dialog the page opens is counted instead of shown.
DIALOG_TRAP = ('window.__dialogs = [];'
               'for (const name of ["alert", "confirm", "prompt", "print"])'
               '  window[name] = (...args) => { window.__dialogs.push(name + ":" + args.join(",")); };')


def main():
    page, desktop, phone = sys.argv[1:4]
    options = webdriver.ChromeOptions()
    options.binary_location = '/usr/bin/chromium'
    for arg in CHROME_ARGS:
        options.add_argument(arg)
    options.set_capability('goog:loggingPrefs', {'browser': 'ALL', 'performance': 'ALL'})
    from selenium.webdriver.remote.remote_connection import RemoteConnection
    RemoteConnection.set_timeout(TIMEOUT)
    browser = webdriver.Chrome(service=Service('/usr/bin/chromedriver'), options=options)
    try:
        browser.set_page_load_timeout(TIMEOUT)
        browser.set_script_timeout(TIMEOUT)
        browser.execute_cdp_cmd('Page.addScriptToEvaluateOnNewDocument', {'source': DIALOG_TRAP})
        browser.execute_cdp_cmd('Network.enable', {})
        url = 'file://' + page
        browser.get(url)
        print(json.dumps(probe(browser, url, desktop, phone)))
    finally:
        browser.quit()


def probe(browser, url, desktop, phone):
    js = browser.execute_script
    seen = {}
    seen['cases'] = js('return Array.from(document.querySelectorAll("section.case, ul.skipped li"), e => ({'
                       'name: e.querySelector(".case-name").textContent, status: e.dataset.status || "skip",'
                       'failsRun: e.dataset.failsRun === "1", inPassing: !!e.closest("details.passing")}))')
    # Markup a name could have injected: only the page's own pictures (class px) and no event attribute.
    seen['foreignImages'] = js('return document.querySelectorAll("img:not(.px)").length')
    seen['eventAttributes'] = js('return Array.from(document.querySelectorAll("*")).filter('
                                 'e => Array.from(e.attributes).some(a => a.name.startsWith("on"))).length')
    seen['scripts'] = js('return document.scripts.length')
    seen['links'] = js('return Array.from(document.querySelectorAll("a[href]"), a => a.getAttribute("href"))')

    viewer = 'document.querySelector(".viewer")'
    ref = viewer + '.querySelector("img.ref")'

    def click_mode(mode):
        browser.find_element('css selector', '.viewer input[value="%s"]' % mode).click()
        return js('return %s.dataset.mode' % viewer)

    def shown():  # the picture the pointer's place shows: elementFromPoint skips a hidden one
        return js('const s = %s.querySelector(".stage").getBoundingClientRect();'
                  'const e = document.elementFromPoint(s.left + s.width * 0.75, s.top + s.height / 2);'
                  'return e ? e.className : ""' % viewer)

    # Slide: the reference clipped from the slider's position; moved as a person's drag would end.
    seen['slideMode'] = click_mode('slide')
    browser.execute_script('arguments[0].scrollIntoView({block: "center"})',
                           browser.find_element('css selector', '.viewer'))
    seen['clipBefore'] = js('return getComputedStyle(%s).clipPath' % ref)
    js('const r = %s.querySelector("input.split"); r.value = "20";'
       'r.dispatchEvent(new Event("input", {bubbles: true}))' % viewer)
    seen['clipAfter'] = js('return getComputedStyle(%s).clipPath' % ref)

    # Hover-flip: the pointer away from the picture, then over it (real pointer moves).
    seen['flipMode'] = click_mode('flip')
    ActionChains(browser).move_to_element(browser.find_element('css selector', 'h1')).perform()
    seen['shownAway'] = shown()
    seen['refVisibilityAway'] = js('return getComputedStyle(%s).visibility' % ref)
    ActionChains(browser).move_to_element(browser.find_element('css selector', '.viewer .stage')).perform()
    seen['shownOver'] = shown()
    seen['refVisibilityOver'] = js('return getComputedStyle(%s).visibility' % ref)

    # Blend and 2-up.
    seen['blendMode'] = click_mode('blend')
    js('const r = %s.querySelector("input.blend"); r.value = "30";'
       'r.dispatchEvent(new Event("input", {bubbles: true}))' % viewer)
    seen['blendOpacity'] = js('return getComputedStyle(%s).opacity' % ref)
    seen['twoUpMode'] = click_mode('2up')
    seen['twoUp'] = js('const n = %s.querySelector("img.new").getBoundingClientRect();'
                       'const r = %s.getBoundingClientRect(); return [n.right, r.left, n.top, r.top]' % (viewer, ref))

    # Zoom: pixelated, and the picture's CSS width follows the menu.
    seen['rendering'] = js('return getComputedStyle(%s).imageRendering' % ref)
    js('const z = document.querySelector("select.zoom"); z.value = "2";'
       'z.dispatchEvent(new Event("change", {bubbles: true}))')
    seen['zoom2Width'] = js('return %s.getBoundingClientRect().width' % ref)
    seen['naturalWidth'] = js('return %s.naturalWidth' % ref)

    # j / k from the page's top.
    js('document.activeElement && document.activeElement.blur(); window.scrollTo(0, 0)')
    keys = []
    for key in ['j', 'j', 'k']:
        ActionChains(browser).send_keys(key).perform()
        keys.append(js('const a = document.activeElement.closest("section.case");'
                       'return a ? a.querySelector(".case-name").textContent : ""'))
    seen['keys'] = keys

    # What the page loaded and said: resources, requests past data: and the page itself, console, dialogs.
    seen['resources'] = js('return performance.getEntriesByType("resource").map(e => e.name)')
    seen['dialogs'] = js('return window.__dialogs')
    try:
        seen['dialogs'].append('native:' + browser.switch_to.alert.text)
    except NoAlertPresentException:
        pass

    # Screenshots of the page as it opens: as a desktop and as a phone (390 × 844 CSS pixels) show it.
    browser.get(url)
    browser.save_screenshot(desktop)
    browser.execute_cdp_cmd('Emulation.setDeviceMetricsOverride',
                            {'width': 390, 'height': 844, 'deviceScaleFactor': 2, 'mobile': True})
    seen['phoneWidths'] = js('return [window.innerWidth, document.documentElement.scrollWidth]')
    browser.save_screenshot(phone)
    browser.execute_cdp_cmd('Emulation.clearDeviceMetricsOverride', {})

    requests = []
    for entry in browser.get_log('performance'):
        message = json.loads(entry['message'])['message']
        if message.get('method') == 'Network.requestWillBeSent':
            requested = message['params']['request']['url']
            if not requested.startswith('data:') and requested != url:
                requests.append(requested)
    seen['requests'] = requests
    seen['console'] = [e['message'] for e in browser.get_log('browser')]

    # The policy itself: an inline handler put on the page now (as markup past the escaping would be) is
    # not run.
    seen['injectedHandlerRan'] = js('window.__ran = false; const b = document.createElement("button");'
                                    'b.setAttribute("onclick", "window.__ran = true"); document.body.append(b);'
                                    'b.click(); return window.__ran')
    return seen


if __name__ == '__main__':
    main()
