// Pod ground station: the two DOM helpers the commands and queue panels build their markup with.

/** A new [tag] element with [attrs], appended to [parent] when given, holding [text] when given. */
export function h(tag, attrs = {}, parent = null, text = null) {
  const node = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) node.setAttribute(k, v);
  if (text != null) node.textContent = text;
  if (parent) parent.appendChild(node);
  return node;
}

/** Sets [node]'s text only when it changed, so a person (or a test) reading it is not raced by redraws. */
export function text(node, value) {
  if (node.textContent !== value) node.textContent = value;
}
