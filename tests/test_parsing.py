from meceng.agents.parsing import extract_code, parse_components

KNOWN = ("Ground", "MassPoint", "SpringDamper", "DistanceConstraint")


def test_components_from_xml_like_list() -> None:
    answer = "Sure.\n<components>\n<component>Ground</component>\n<component>mass point</component>\n</components>"
    parsed = parse_components(answer, KNOWN)
    assert parsed.error is None and parsed.names == ("Ground", "MassPoint")


def test_components_comma_list_and_unknown_names_kept_apart() -> None:
    parsed = parse_components("<components>SpringDamper, Wheel, - Ground</components>", KNOWN)
    assert parsed.names == ("SpringDamper", "Ground") and parsed.unknown == ("Wheel",)


def test_thinking_block_is_ignored() -> None:
    answer = "<think><components><component>Ground</component></components></think>" \
             "<components><component>MassPoint</component></components>"
    assert parse_components(answer, KNOWN).names == ("MassPoint",)


def test_malformed_component_answers_are_errors_not_crashes() -> None:
    for answer in ("", "I need a mass point", "<components></components>", "<components> Foo </components>", None):
        parsed = parse_components(answer, KNOWN)  # type: ignore[arg-type]
        assert parsed.error and parsed.names == ()


def test_code_block_with_assemble_is_chosen() -> None:
    answer = "Here:\n```bash\npip install exudyn\n```\n```python\nprint(1)\n```\n" \
             "```python\nimport exudyn as exu\nmbs.Assemble()\n```\nDone."
    assert extract_code(answer).code == "import exudyn as exu\nmbs.Assemble()\n"


def test_unfenced_program_and_missing_code() -> None:
    assert extract_code("import exudyn as exu\nx = 1\n").code is not None
    missing = extract_code("The answer is 42.")
    assert missing.code is None and "no Python code block" in (missing.error or "")


def test_every_prompt_variant_keeps_the_answer_schema() -> None:
    from meceng.agents.prompts import CODE_TEMPLATES, SELECT_TEMPLATES, code_prompt, select_prompt

    assert sorted(SELECT_TEMPLATES) == [f"CI{i}" for i in range(1, 7)]
    assert sorted(CODE_TEMPLATES) == [f"MBS{i}" for i in range(1, 5)]
    for name in SELECT_TEMPLATES:
        text = select_prompt(name, "DESCRIPTION-X", "- Ground: ground")
        assert "DESCRIPTION-X" in text and "- Ground: ground" in text and "<components>" in text
    for name in CODE_TEMPLATES:
        text = code_prompt(name, "DESCRIPTION-X", "CONTEXT-Y")
        assert "DESCRIPTION-X" in text and "CONTEXT-Y" in text and "```python" in text
