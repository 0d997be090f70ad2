"""Renderers: text tables here; SVG and plots import their heavy libraries lazily."""
