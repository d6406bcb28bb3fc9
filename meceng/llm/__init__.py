"""Talking to language-model servers: one async interface over Ollama, OpenAI-compatible servers
(vLLM, SGLang, llama.cpp), Anthropic's API and the ``gold`` backend.

``types`` (settings, requests, answers, errors) <- ``scheduler`` (slots and retries per endpoint)
<- ``backend_*`` (one module per wire format) <- ``factory`` (picks one); ``messages`` is the
agent's conversation format, ``cache`` the response cache a resumed run replays.
"""
